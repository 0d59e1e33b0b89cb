#include "render/trace/trace_writer.h"

#include "render/jobs/csv_field.h"
#include "render/jobs/json_writer.h"
#include "sim/world/diagnostics.h"
#include "sim/world3d/diagnostics.h"

namespace render::trace {
using render::jobs::csvField;
using render::jobs::formatNumber;

TraceWriter::TraceWriter(std::ostream& out, const sim::scene::SceneDef& def) : out_(out), def_(def) {
  out_ << "t,body,x,y,angle,vx,vy,omega,kinetic_energy\n";
}

void TraceWriter::rows(const sim::world::World& w) {
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const sim::core::Body& b = w.bodies[i];
    out_ << formatNumber(w.time) << ',' << csvField(def_.bodies[i].name) << ',' << formatNumber(b.x.x()) << ','
         << formatNumber(b.x.y()) << ',' << formatNumber(b.angle) << ',' << formatNumber(b.v.x()) << ',' << formatNumber(b.v.y())
         << ',' << formatNumber(b.omega) << ',' << formatNumber(sim::world::kineticEnergy(b).total()) << '\n';
  }
}

TraceWriter3d::TraceWriter3d(std::ostream& out, const sim::scene3d::SceneDef& def) : out_(out), def_(def) {
  out_ << "t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
}

void TraceWriter3d::rows(const sim::world3d::World& w) {
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const sim::world3d::Body& b = w.bodies[i];
    out_ << formatNumber(w.time) << ',' << csvField(def_.bodies[i].name);
    for (double x : {b.x.x(), b.x.y(), b.x.z(), b.q.w(), b.q.x(), b.q.y(), b.q.z(), b.v.x(), b.v.y(), b.v.z(), b.omega.x(),
                     b.omega.y(), b.omega.z(), sim::world3d::kineticEnergy(b).total()})
      out_ << ',' << formatNumber(x);
    out_ << '\n';
  }
}

}  // namespace render::trace

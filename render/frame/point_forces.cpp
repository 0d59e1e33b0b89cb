#include "render/frame/point_forces.h"

namespace render::frame {

std::vector<AppliedForce> pointForcesOn(const sim::world::World& world, int body) {
  std::vector<AppliedForce> out;
  const sim::core::Body& b = world.bodies[body];
  for (const sim::core::PointForce& p : world.def().forces.pointForces) {
    if (p.body != body || world.time < p.from || world.time >= p.until) continue;
    out.push_back({b.pose().toWorld(p.point), p.bodyFrame ? b.q().apply(p.force) : p.force});
  }
  return out;
}

double torqueOf(const sim::core::Body& body, const std::vector<AppliedForce>& forces) {
  double tau = 0.0;
  for (const AppliedForce& f : forces) tau += sim::core::cross(f.point - body.x, f.force);
  return tau;
}

}  // namespace render::frame

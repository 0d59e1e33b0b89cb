#include "render/golden/sample3d.h"

#include <cmath>

#include "sim/world3d/diagnostics.h"

namespace render::golden {
using namespace render::trace;

TraceSample sampleOf(const sim::world3d::Body& b, double t) {
  TraceSample s{t, b.x.x(), b.x.y(), 0.0, b.v.x(), b.v.y(), b.omega.z(), sim::world3d::kineticEnergy(b).total(), 0};
  s.z = b.x.z(), s.vz = b.v.z(), s.wx = b.omega.x(), s.wy = b.omega.y();
  s.qw = b.q.w(), s.qx = b.q.x(), s.qy = b.q.y(), s.qz = b.q.z();
  return s;
}

double rotationBetween(const TraceSample& a, const TraceSample& e) {
  const double w = e.qw * a.qw + e.qx * a.qx + e.qy * a.qy + e.qz * a.qz;
  const double x = e.qw * a.qx - a.qw * e.qx - (e.qy * a.qz - e.qz * a.qy);
  const double y = e.qw * a.qy - a.qw * e.qy - (e.qz * a.qx - e.qx * a.qz);
  const double z = e.qw * a.qz - a.qw * e.qz - (e.qx * a.qy - e.qy * a.qx);
  return 2.0 * std::atan2(std::hypot(x, y, z), std::abs(w));
}

}  // namespace render::golden

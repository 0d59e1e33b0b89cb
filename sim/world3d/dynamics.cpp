#include "sim/world3d/dynamics.h"

namespace sim::world3d {

Vec3 angularAcceleration(const Body& body, const Quat& q, const Vec3& omega, const Vec3& torque) {
  const Mat3 r = rotationMatrix(q);
  // L = R I_b Rᵀ ω and I⁻¹ = R I_b⁻¹ Rᵀ, each product taken through body axes, where I_b is constant
  const Vec3 angularMomentum = r * (body.inertiaBody * (r.transpose() * omega));
  return r * (body.invInertiaBody * (r.transpose() * (torque - omega.cross(angularMomentum))));
}

void Dynamics::rates(const States& y, Rates& out) const {
  Wrenches w;
  wrenches(y, w);
  out.resize(y.size());
  for (size_t i = 0; i < y.size(); ++i) {
    const Body& b = bodies[i];
    const BodyState& s = y[i];
    out[i] = {s.v, quaternionRate(s.q, s.omega), b.invMass * w[i].force, angularAcceleration(b, s.q, s.omega, w[i].torque)};
  }
}

}  // namespace sim::world3d

// The dynamics of a free rigid body in 3D (notes: "Rigid body velocity", "Forces and torques"):
//   ẋ = v,   q̇ = ½ (0, ω) q,   m v̇ = f,   dL/dt = τ with L = I ω, I = R I_b Rᵀ,
// the last being Euler's equations I_b ω̇_b + ω_b × I_b ω_b = τ_b written in the world frame:
// dL/dt = İ ω + I ω̇ = ω × I ω + I ω̇, so ω̇ = I⁻¹ (τ − ω × I ω).
#pragma once

#include <vector>

#include "sim/world3d/forces.h"

namespace sim::world3d {

// time derivative of one body's state
struct BodyRate {
  Vec3 xDot = Vec3::Zero();
  Quat qDot = Quat(0, 0, 0, 0);  // a tangent four-vector, not a rotation
  Vec3 vDot = Vec3::Zero();
  Vec3 omegaDot = Vec3::Zero();
};

using States = std::vector<BodyState>;
using Rates = std::vector<BodyRate>;

// what an integrator needs of the world: the bodies' mass properties and the forces on them
struct Dynamics {
  const std::vector<Body>& bodies;  // mass properties; their states are the integrator's
  const ForceSet& forces;
  double window = 0.0;  // a time inside the step: decides which timed forces are on

  // net force and torque on every body at the states y
  void wrenches(const States& y, Wrenches& out) const { forces.accumulate(window, bodies, y, out); }
  // the state's time derivative at y, by the equations above
  void rates(const States& y, Rates& out) const;
};

// ω̇ = I⁻¹ (τ − ω × I ω) for one body at orientation q (Euler's equations, world frame)
Vec3 angularAcceleration(const Body& body, const Quat& q, const Vec3& omega, const Vec3& torque);

}  // namespace sim::world3d

// A rigid body in 3D: the notes' state (x, q, v, ω) plus its constant mass properties in body axes.
#pragma once

#include "sim/world3d/math.h"
#include "sim/world3d/shape.h"

namespace sim::world3d {

// what an integrator advances: 7 numbers of position for 6 degrees of freedom (|q| = 1), and the
// velocities; v and ω are in the world frame
struct BodyState {
  Vec3 x = Vec3::Zero();      // center of mass, world
  Quat q = Quat::Identity();  // [w x y z], body to world: r = x + R(q) r_b
  Vec3 v = Vec3::Zero();
  Vec3 omega = Vec3::Zero();

  Mat3 rotation() const { return rotationMatrix(q); }
  // r = x + R r_b
  Vec3 toWorld(const Vec3& rb) const { return x + rotation() * rb; }
  // velocity of the body point at world position r: ṙ = v + ω × r′, r′ = r − x
  Vec3 pointVelocity(const Vec3& r) const { return v + omega.cross(r - x); }
};

struct Body : BodyState {
  Shape shape;  // in body coordinates, centered on the center of mass
  double mass = 1.0, invMass = 1.0;
  double restitution = 0.5;                // c_r, combined per pair as in 2D (contact3d.h)
  double friction = 0.0;                   // Coulomb μ
  bool frictionNamed = true;               // μ named by the body or the world's default (2D's rule: contact.h)
  Mat3 inertiaBody = Mat3::Identity();     // I_b about the center, body axes (a full tensor)
  Mat3 invInertiaBody = Mat3::Identity();  // I_b⁻¹
  // I_b's eigenvalues, ascending, and its unit eigenvectors as columns, in body coordinates: found
  // once here, for the check below and for the splitting integrator, which rotates about them
  Vec3 principalMoments = Vec3::Ones();
  Mat3 principalAxes = Mat3::Identity();

  // throws std::invalid_argument naming the fault unless m > 0 and I_b is symmetric with positive
  // principal moments that satisfy the triangle inequality I₁ + I₂ ≥ I₃ (as every solid's do)
  void setMassProperties(double mass, const Mat3& inertiaBody);

  const BodyState& state() const { return *this; }
  void setState(const BodyState& s) { static_cast<BodyState&>(*this) = s; }

  // the world inertia I = R I_b Rᵀ and its inverse R I_b⁻¹ Rᵀ at orientation q (for a unit q;
  // evaluated as they stand when q has drifted, which is what shows the drift)
  Mat3 worldInertia(const Quat& at) const;
  Mat3 worldInverseInertia(const Quat& at) const;
  Mat3 worldInertia() const { return worldInertia(q); }
  Mat3 worldInverseInertia() const { return worldInverseInertia(q); }
  // L = I ω about the center, world frame
  Vec3 angularMomentum() const { return worldInertia() * omega; }

  // the notes' impulse j at world point r: Δv = j/m, Δω = I⁻¹ (r′ × j)
  void applyImpulse(const Vec3& r, const Vec3& j);
};

// a body of uniform density (kg/m³) filling `shape`, at rest at the origin
Body makeBody(const Shape& shape, double density);
// a body whose mass and inertia are given outright (its shape then carries no mass)
Body makeBody(const Shape& shape, double mass, const Mat3& inertiaBody);

}  // namespace sim::world3d

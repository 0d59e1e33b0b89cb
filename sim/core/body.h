// A rigid body: the notes' state (x, q, v, ω) plus the constant mass properties; the orientation is
// stored once, as the angle θ, and q = (cos θ, sin θ) derived from it.
#pragma once

#include <limits>

#include "sim/core/math.h"
#include "sim/core/shape.h"

namespace sim::core {

// what an integrator advances: the angle θ is integrated, q = (cos θ, sin θ) follows from it, so
// q stays unit length and rotation at constant ω is exact (2D rotations commute)
struct BodyState {
  Vec2 x = Vec2::Zero();
  double angle = 0.0;
  Vec2 v = Vec2::Zero();
  double omega = 0.0;

  // the notes' q = (cos θ, sin θ), derived from the one stored orientation
  Rot q() const { return Rot::fromAngle(angle); }
  Pose pose() const { return {x, q()}; }
};

struct Body {
  Shape shape;  // in body coordinates, origin at the center of mass
  double mass = 1.0, invMass = 1.0;
  double inertia = 1.0, invInertia = 1.0;
  bool isStatic = false;
  double restitution = 0.5;  // c_r, combined per pair (contact.h)
  double friction = 0.0;     // Coulomb μ
  // μ was named, by the body or by the world's default: a pair of which only one body names μ takes
  // that μ (contact.h: combinedFriction)
  bool frictionNamed = true;

  Vec2 x = Vec2::Zero();  // center of mass, world
  double angle = 0.0;     // continuous (not wrapped), counter-clockwise: the one stored orientation
  Vec2 v = Vec2::Zero();
  double omega = 0.0;  // counter-clockwise positive

  // the notes' q = (cos θ, sin θ), derived: a solver that turns the body changes the angle alone,
  // and q can never lag behind it
  Rot q() const { return Rot::fromAngle(angle); }
  Pose pose() const { return {x, q()}; }

  BodyState state() const { return {x, angle, v, omega}; }
  void setState(const BodyState& s) {
    x = s.x;
    angle = s.angle;
    v = s.v;
    omega = s.omega;
  }
  // velocity of the body point at world position r: v + ω × r′ with r′ = r - x
  Vec2 pointVelocity(const Vec2& r) const { return v + cross(omega, r - x); }

  // static bodies have infinite mass: zero inverses, so impulses and forces do nothing
  void makeStatic() {
    isStatic = true;
    mass = inertia = std::numeric_limits<double>::infinity();
    invMass = invInertia = 0.0;
    v.setZero();
    omega = 0.0;
  }
};

}  // namespace sim::core

// Small 2D vector algebra on top of Eigen, with the notes' names: x, q = (cos θ, sin θ), ω × r.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace sim::core {

using Vec2 = Eigen::Vector2d;

// a 2D rotation stored as q = (c, s), the first column of R (notes: "Representing rigid body state")
struct Rot {
  double c = 1.0;
  double s = 0.0;

  static Rot fromAngle(double angle) { return {std::cos(angle), std::sin(angle)}; }
  // R r_b: body to world
  Vec2 apply(const Vec2& r) const { return {c * r.x() - s * r.y(), s * r.x() + c * r.y()}; }
  // Rᵀ r: world to body
  Vec2 applyInverse(const Vec2& r) const { return {c * r.x() + s * r.y(), -s * r.x() + c * r.y()}; }
  // this rotation after `inner`: R R_inner
  Rot then(const Rot& inner) const { return {c * inner.c - s * inner.s, s * inner.c + c * inner.s}; }
};

// the scalar 2D cross product a × b (the z part of the 3D one)
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// ω × r for an angular velocity ω along z
inline Vec2 cross(double w, const Vec2& r) { return {-w * r.y(), w * r.x()}; }

// r × ω for an angular velocity ω along z
inline Vec2 cross(const Vec2& r, double w) { return {w * r.y(), -w * r.x()}; }

// a pose: where a body's frame is in the world
struct Pose {
  Vec2 x = Vec2::Zero();
  Rot q;
  // r = x + R r_b
  Vec2 toWorld(const Vec2& rb) const { return x + q.apply(rb); }
  Vec2 toBody(const Vec2& r) const { return q.applyInverse(r - x); }
  // a frame given in this one's coordinates (a body's part), in the world
  Pose then(const Pose& inner) const { return {toWorld(inner.x), q.then(inner.q)}; }
};

inline bool isFinite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

}  // namespace sim::core

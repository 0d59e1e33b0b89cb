// A 3D body's contacts with a static plane or another body, and what the collision methods record
// of them: the 2D world's contact.h in 3D (the notes' collision slides hold in vector form).
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/world3d/body.h"

namespace sim::world3d {

// a static half-space, solid behind its unit normal (a floor, a wall): infinite mass, never moves
struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, out of the solid
  double restitution = 0.5;
  double friction = 0.0;
  bool frictionNamed = false;
};

// a box touches a plane at up to its 8 corners
inline constexpr int kMaxContactPoints = 8;

struct ContactPoint3 {
  Vec3 point = Vec3::Zero();  // world: on A's surface (a plane), midway between the surfaces (two spheres)
  double separation = 0.0;    // along the normal, m; negative: overlap
  int feature = 0;            // which point of A's shape: a box's corner index, else 0
  // accumulated impulses, warm started from the same pair's same feature last step (Catto 2006)
  double normalImpulse = 0.0;
  Vec3 tangentImpulse = Vec3::Zero();
};

struct Contact3 {
  int a = 0;                    // a body
  int b = -1;                   // another body (b > a), or a plane: −1 − its index
  Vec3 normal = Vec3::UnitZ();  // from B to A
  int count = 0;
  ContactPoint3 points[kMaxContactPoints];
  double restitution = 0.0, friction = 0.0;
  bool withPlane() const { return b < 0; }
  int plane() const { return -1 - b; }
};

// one impulse the collision response applied: γ along n̂ at `point`, j = γ n̂ + the friction impulse
// to A (and −j to B)
struct ImpactRecord3 {
  double t = 0.0;
  int a = 0, b = -1;  // as Contact3's
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double impulse = 0.0;                // γ
  Vec3 tangentImpulse = Vec3::Zero();  // friction, in the contact's plane
  double vnBefore = 0.0, vnAfter = 0.0;
};

// pair coefficients, as in 2D (sim/world/contact.h): the larger restitution; the geometric mean of
// two named frictions, else the one that is named, else the default both carry
inline double combinedRestitution(double a, double b) { return std::max(a, b); }
inline double combinedFriction(double a, bool aNamed, double b, bool bNamed) {
  if (aNamed == bNamed) return std::sqrt(a * b);
  return aNamed ? a : b;
}

}  // namespace sim::world3d

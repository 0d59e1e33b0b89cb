// A touching pair and what the collision methods record about it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <tuple>
#include <vector>

#include "sim/collision/collide.h"
#include "sim/core/collision_methods.h"
#include "sim/core/body.h"
#include "sim/core/enum_names.h"

namespace sim::world {

// the collision methods by name (shared with 3D)

// the numbers soft_step solves its contacts in (`sim: {precision: ...}`): double, or float as Box2D
// v3 does (half the width of a SIMD lane: faster on piles, to float's round-off)
enum class Precision { Double, Float };
inline constexpr sim::core::EnumNames<Precision, 2> kPrecisionNames{{{
    {Precision::Double, "double"},
    {Precision::Float, "float"},
}}};
inline std::string_view precisionName(Precision p) { return kPrecisionNames.name(p); }
inline std::optional<Precision> precisionFromName(std::string_view name) { return kPrecisionNames.parse(name); }

// what a manifold point carries from one step to the next: its accumulated impulses, the warm
// start of the stack solvers (Catto 2006); each solver keeps its per-step data in its own records
struct ContactPointState {
  double normalImpulse = 0.0;   // accumulated, clamped ≥ 0
  double tangentImpulse = 0.0;  // accumulated, clamped to ±μ·normalImpulse
};

// the direction friction acts along at a contact of normal n̂: n̂ turned a quarter counterclockwise
inline sim::core::Vec2 tangentOf(const sim::core::Vec2& n) { return {-n.y(), n.x()}; }

struct Contact {
  int a = 0, b = 0;          // body indices, a < b
  int partA = 0, partB = 0;  // which part of each body touches (0 for a body of one shape)
  sim::collision::Manifold manifold;
  double restitution = 0.0;
  double friction = 0.0;
  ContactPointState state[2];
};

// one impulse the collision response applied: the notes' γ along n̂ at `point`, j = γ n̂ to A
struct ImpactRecord {
  double t = 0.0;
  int a = 0, b = 0;
  sim::core::Vec2 point = sim::core::Vec2::Zero();
  sim::core::Vec2 normal = sim::core::Vec2::UnitY();  // from B to A
  double impulse = 0.0;                               // γ
  double tangentImpulse = 0.0;                        // friction, along (−n_y, n_x)
  double vnBefore = 0.0, vnAfter = 0.0;
};

// a contact that the event method turned into resting contact (impacts piling up in finite time)
struct RestingRecord {
  double t = 0.0;
  int a = 0, b = 0;
  // the pair still slides or turns while it touches (a plastic impact of a spinning bar): it stays in
  // contact rather than coming to rest
  bool moving = false;
};

// a contact's pair of parts, the order the contact lists are sorted in: by body, then by part
inline std::tuple<int, int, int, int> pairKey(const Contact& c) { return {c.a, c.partA, c.b, c.partB}; }

// what a contact's points carry to the same pair's contact next step: their features and impulses
struct CarriedPoints {
  int count = 0;
  sim::collision::FeatureId id[2] = {0, 0};
  ContactPointState state[2];
};
CarriedPoints carriedPoints(const Contact& c);

// one contact's points: each starts from the impulses of `previous`'s point of the same features
// (the same pair's contact last step: the warm start of the stack solvers, Catto 2006)
void carryImpulses(const CarriedPoints& previous, Contact& c);
inline void carryImpulses(const Contact& previous, Contact& c) { carryImpulses(carriedPoints(previous), c); }

// pair coefficients (documented in scenes/README.md): the larger restitution (a bouncy ball
// bounces on any floor, as in Box2D) and the geometric mean of the frictions (inline: every pair
// of every step asks, and the call was 1.4 % of a step on the 5,050-box pyramid)
inline double combinedRestitution(double a, double b) { return std::max(a, b); }
inline double combinedFriction(double a, double b) { return std::sqrt(a * b); }
// a pair of bodies: the geometric mean when both name μ, else the μ of the one that names it (a
// crate with μ = 0.4 on a floor that names none slides to a stop, where √(0.4 · 0) would let it
// slide on without a word), else the world's default that both carry
inline double combinedFriction(const sim::core::Body& a, const sim::core::Body& b) {
  if (a.frictionNamed == b.frictionNamed) return combinedFriction(a.friction, b.friction);
  return a.frictionNamed ? a.friction : b.friction;
}

}  // namespace sim::world

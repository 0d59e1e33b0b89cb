// Contact recycling for `soft_step` (sim: {recycle: ...}), the idea of Box2D v3's contact
// recycling (physics_world.c, after the persistent manifolds of PhysX), written anew: a touching
// pair whose relative pose moved less than a distance since its manifold was made keeps that
// manifold, its points carried with the two bodies and their separations updated from that motion,
// instead of being collided again. A resting pile then costs no narrow phase; what it gives up is
// a manifold made where the bodies are (measured in sim/README.md: soft_step's contact recycling).
#pragma once

#include <cstdint>

#include "sim/collision/collide.h"

namespace sim::world {

// a manifold as it was made, with what carrying it needs
struct RecycleEntry {
  std::uint64_t key = ~std::uint64_t{0};  // the proxy pair (first << 32 | second)
  bool valid = false;                     // a manifold with points was made
  sim::core::Rot qA, qB;                  // the two shapes' rotations then
  sim::core::Pose relative;               // B's shape in A's frame then
  // each point from each shape's origin then, in the world
  sim::core::Vec2 anchorA[2] = {sim::core::Vec2::Zero(), sim::core::Vec2::Zero()},
                  anchorB[2] = {sim::core::Vec2::Zero(), sim::core::Vec2::Zero()};
  double baseSeparation[2] = {0.0, 0.0};
  sim::collision::Manifold manifold;
};

// the entry of manifold `m` made with the shapes at `a` and `b`
RecycleEntry recycleEntry(std::uint64_t key, const sim::core::Pose& a, const sim::core::Pose& b,
                          const sim::collision::Manifold& m);

// `entry`'s manifold carried to the shapes at `a` and `b`: each point's anchors turned with its
// shape, its separation changed by how far the two material points moved apart along the normal;
// none when either shape turned more than acos(kRecycleCos) since, or B moved relative to A (its
// farthest point `extent` from its origin) by `distance` or more. Written into `out` (untouched
// when there is none): returned in an optional, its copy out read the stack in pieces wider than
// they were written, a stall that was 3 % of a step on the 5,050-box pyramid
bool recycledManifold(const RecycleEntry& entry, const sim::core::Pose& a, const sim::core::Pose& b, double extent,
                      double distance, sim::collision::Manifold& out);

// whether `m` holds what `entry`'s manifold holds but its points' places and separations (its
// normal, count and features), the points' features distinct: then a contact whose manifold is `m`
// was made from `entry`, and recycledPointsInto may carry its points where they lie, their impulses
// with them
bool madeFrom(const RecycleEntry& entry, const sim::collision::Manifold& m);

// recycledManifold written into a manifold made from `entry` (madeFrom): its points and separation
// alone (the same manifold to the bit); whether it recycled (else `m` is untouched)
bool recycledPointsInto(const RecycleEntry& entry, const sim::core::Pose& a, const sim::core::Pose& b, double extent,
                        double distance, sim::collision::Manifold& m);

}  // namespace sim::world

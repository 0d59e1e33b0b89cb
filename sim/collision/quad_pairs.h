// Four pairs of four-sided polygons collided at once (the boxes of a pile, the common pair): the
// same separating-axis search and clipping as collide()'s polygon pair, each operation the same in
// the same order in AVX2's four lanes, so that the manifolds are collide()'s to the bit
// (tests/sim/collision/quad_pairs_test.cpp). A lane whose first clipping keeps no point of a
// touching pair (the best edge's clipping, a corner against a corner) is collided again by
// collide() itself.
#pragma once

#include "sim/collision/collide.h"

namespace sim::collision {

constexpr int kQuadLanes = 4;

// both shapes are polygons of four vertices
inline bool isQuadPair(const PlacedShape& a, const PlacedShape& b) {
  return a.vertices.size() == 4 && b.vertices.size() == 4 && a.shape->kind == sim::core::ShapeKind::Polygon &&
         b.shape->kind == sim::core::ShapeKind::Polygon;
}

// collide(*a[k], *b[k], margin, sideSlack) for k = 0 to 3, every pair a quad pair
void collideQuadPairs(const PlacedShape* const a[kQuadLanes], const PlacedShape* const b[kQuadLanes], double margin,
                      Manifold out[kQuadLanes], double sideSlack = 0.0);

}  // namespace sim::collision

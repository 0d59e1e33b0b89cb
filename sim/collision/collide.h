// Contact detection: pure functions of two shapes and two poses.
//
// Normal convention (the notes' "Collisions: two rigid bodies"): the manifold normal n̂ points
// from B to A, out of B, so that v_n = n̂·(v_A − v_B + ω_A × r_A − ω_B × r_B) is negative when
// the bodies approach and the impulse j = γ n̂ goes to A, −j to B.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/core/math.h"
#include "sim/core/shape.h"

namespace sim::collision {

// names the two features (vertex or edge, with its index) that make a contact point: 32 bits a
// feature, so that every index a polygon may have (sim: max_vertices, an int) has its own id
using FeatureId = std::uint64_t;

struct ManifoldPoint {
  sim::core::Vec2 point = sim::core::Vec2::Zero();  // world, midway between the two surfaces
  double separation = 0.0;                          // negative when overlapping
  FeatureId id = 0;                                 // the features that make it; stable from step to step
};

// the separating-axis bookkeeping of the notes' slide, kept for drawing
struct SatFeatures {
  bool valid = false;        // both shapes are polygons
  double separation = 0.0;   // separation(P, Q): NEGATIVE when they overlap (see sat())
  bool referenceOnA = true;  // which polygon owns the reference edge
  int referenceEdge = -1;    // edge i runs from vertex i to i + 1 of its polygon
  int incidentVertex = -1;   // vertex of the other polygon
};

struct Manifold {
  sim::core::Vec2 normal = sim::core::Vec2::UnitY();  // from B to A
  int count = 0;                                      // 0, 1 or 2 points
  ManifoldPoint points[2];
  SatFeatures sat;
  // the smallest separation of the points, or the gap when count is 0 (a lower bound on the
  // distance between the shapes: what the event method advances by)
  double separation = 0.0;
};

// the notes' separating-axis test for convex polygons in world coordinates:
//   distance(e → x) = normal(e)·(x − point_on(e))
//   separation(e → Q) = min over vertices v of Q of distance(e → v)
//   separation(P → Q) = max over edges e of P of separation(e → Q)
//   separation(P, Q) = max(separation(P → Q), separation(Q → P))
// The notes' slide prints "overlap(P, Q): separation(P, Q) > 0"; with this definition of distance
// a positive separation is a gap, so the polygons overlap when the separation is NEGATIVE.
SatFeatures sat(const sim::core::Shape& a, const sim::core::Pose& pa, const sim::core::Shape& b, const sim::core::Pose& pb);

// a shape where its body is: a polygon's vertices and edge normals in world coordinates, computed
// once for its bounds and every pair it is in (a box in a pile is in four)
struct PlacedShape {
  const sim::core::Shape* shape = nullptr;
  sim::core::Pose pose;
  std::vector<sim::core::Vec2> vertices, normals;  // polygons only
};
// `shape` at `pose`, into `out` (its storage reused)
void place(const sim::core::Shape& shape, const sim::core::Pose& pose, PlacedShape& out);

// the contact manifold of two shapes; points are kept while their separation is at most `margin`;
// a polygon pair clips its incident edge to the reference edge's side planes moved out by
// `sideSlack` (0: the edge's own ends; Box2D's skin, settings::kClipSideSlack, for the sequential
// solver), so a point may lie that far past the reference edge's end
Manifold collide(const sim::core::Shape& a, const sim::core::Pose& pa, const sim::core::Shape& b, const sim::core::Pose& pb,
                 double margin, double sideSlack = 0.0);
// the same of two placed shapes (the same numbers: the shapes are placed the same way)
Manifold collide(const PlacedShape& a, const PlacedShape& b, double margin, double sideSlack = 0.0);

// axis-aligned bounds of a shape in a pose (a plane is unbounded)
struct Aabb {
  sim::core::Vec2 lower, upper;
  bool overlaps(const Aabb& o) const {
    return lower.x() <= o.upper.x() && o.lower.x() <= upper.x() && lower.y() <= o.upper.y() && o.lower.y() <= upper.y();
  }
};
Aabb bounds(const sim::core::Shape& shape, const sim::core::Pose& pose);
Aabb bounds(const PlacedShape& placed);

}  // namespace sim::collision

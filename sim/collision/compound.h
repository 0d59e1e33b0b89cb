// Bodies made of parts: each part a convex shape of the same body, collided part against part
// (as Box2D gives a body several fixtures). The pure functions here answer for a compound shape
// what collide.h answers for a convex one.
#pragma once

#include <optional>
#include <vector>

#include "sim/collision/collide.h"

namespace sim::collision {

// where a part of a body at `body` is in the world: the body's pose after the part's
inline sim::core::Pose partPose(const sim::core::Pose& body, const sim::core::ShapePart& part) { return body.then(part.pose); }

// how many convex parts a shape has (1 for a circle, polygon or plane)
inline int partCount(const sim::core::Shape& shape) {
  return shape.kind == sim::core::ShapeKind::Compound ? static_cast<int>(shape.parts.size()) : 1;
}
// part k of a shape and its pose, for a body at `body` (a convex shape is its own part 0)
inline const sim::core::Shape& partShape(const sim::core::Shape& shape, int k) {
  return shape.kind == sim::core::ShapeKind::Compound ? shape.parts[k].shape : shape;
}
inline sim::core::Pose partPoseOf(const sim::core::Shape& shape, int k, const sim::core::Pose& body) {
  return shape.kind == sim::core::ShapeKind::Compound ? partPose(body, shape.parts[k]) : body;
}

// the manifold of one pair of parts
struct PartManifold {
  int partA = 0, partB = 0;
  Manifold manifold;
};

// the manifolds of every pair of parts of a and b closer than `margin`, into `out` (cleared first)
void collideParts(const sim::core::Shape& a, const sim::core::Pose& pa, const sim::core::Shape& b, const sim::core::Pose& pb,
                  double margin, std::vector<PartManifold>& out, double sideSlack = 0.0);

// the manifold of the closest pair of parts (collide()'s answer for a compound: its separation is
// the gap between the shapes)
Manifold closestParts(const sim::core::Shape& a, const sim::core::Pose& pa, const sim::core::Shape& b, const sim::core::Pose& pb,
                      double margin, double sideSlack = 0.0);

// the bounds of a compound at `pose`: its parts' together
Aabb compoundBounds(const sim::core::Shape& shape, const sim::core::Pose& pose);

// the first part of a compound that overlaps one before it by more than `tolerance`, or none
std::optional<int> overlappingPart(const sim::core::Shape& compound, double tolerance);

}  // namespace sim::collision

#include "sim/collision/compound.h"

#include <limits>

namespace sim::collision {
using namespace sim::core;

void collideParts(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin, std::vector<PartManifold>& out,
                  double sideSlack) {
  out.clear();
  for (int i = 0; i < partCount(a); ++i)
    for (int j = 0; j < partCount(b); ++j) {
      const Manifold m = collide(partShape(a, i), partPoseOf(a, i, pa), partShape(b, j), partPoseOf(b, j, pb), margin, sideSlack);
      if (m.count > 0) out.push_back({i, j, m});
    }
}

Manifold closestParts(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin, double sideSlack) {
  Manifold closest;
  closest.separation = std::numeric_limits<double>::infinity();
  for (int i = 0; i < partCount(a); ++i)
    for (int j = 0; j < partCount(b); ++j) {
      const Manifold m = collide(partShape(a, i), partPoseOf(a, i, pa), partShape(b, j), partPoseOf(b, j, pb), margin, sideSlack);
      if (m.separation < closest.separation) closest = m;
    }
  return closest;
}

Aabb compoundBounds(const Shape& shape, const Pose& pose) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Aabb box{Vec2::Constant(kInf), Vec2::Constant(-kInf)};
  for (const ShapePart& part : shape.parts) {
    const Pose p = partPose(pose, part);
    if (part.shape.kind == ShapeKind::Circle) {
      box.lower = box.lower.cwiseMin(p.x - Vec2::Constant(part.shape.radius));
      box.upper = box.upper.cwiseMax(p.x + Vec2::Constant(part.shape.radius));
    }
    for (const Vec2& v : part.shape.vertices) {
      const Vec2 w = p.toWorld(v);
      box.lower = box.lower.cwiseMin(w);
      box.upper = box.upper.cwiseMax(w);
    }
  }
  return box;
}

std::optional<int> overlappingPart(const Shape& compound, double tolerance) {
  const Pose origin;
  for (int j = 1; j < partCount(compound); ++j)
    for (int i = 0; i < j; ++i) {
      const Manifold m = collide(partShape(compound, i), partPoseOf(compound, i, origin), partShape(compound, j),
                                 partPoseOf(compound, j, origin), 0.0);
      if (m.separation < -tolerance) return j;
    }
  return std::nullopt;
}

}  // namespace sim::collision

// Bodies made of parts in the collision layer (compound.cpp): each part a convex shape of one body.
#include <doctest/doctest.h>

#include <vector>

#include "sim/collision/compound.h"

namespace {

using namespace sim::core;

// a T: a 0.1 × 1 handle and a 0.4 × 0.2 head on its top end
Shape hammer() {
  return sim::core::makeCompound({{sim::core::makeBox(0.1, 1.0), {}}, {sim::core::makeBox(0.4, 0.2), {{0, 0.6}, {}}}});
}

}  // namespace

TEST_CASE("a body of parts on a floor: each part that touches has its manifold, the gap is the closest part's") {
  const Shape floor = sim::core::makePlane({0, 1});
  // lying on its side on the floor: the handle and the head both touch
  const Pose lying{{0, 0.2}, Rot::fromAngle(-1.5707963267948966)};
  std::vector<sim::collision::PartManifold> parts;
  sim::collision::collideParts(hammer(), lying, floor, Pose{}, 0.01, parts);
  // the head (0.2 tall) reaches y = 0, the handle's side only y = 0.15: just the head within 1 cm
  REQUIRE(parts.size() == 1);
  CHECK(parts[0].partA == 1);
  CHECK(parts[0].manifold.count == 2);
  CHECK(parts[0].manifold.separation == doctest::Approx(0.0).epsilon(1e-12));
  // a 2 × 1 box and a 1 × 1 box side by side, lying flat: both parts touch, two points each
  const Shape block = sim::core::makeCompound({{sim::core::makeBox(2, 1), {}}, {sim::core::makeBox(1, 1), {{1.5, 0}, {}}}});
  sim::collision::collideParts(block, Pose{{0, 0.5}, {}}, floor, Pose{}, 0.01, parts);
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].manifold.count + parts[1].manifold.count == 4);
  // collide() answers with the closest pair: the gap from the lowest part
  const sim::collision::Manifold m = sim::collision::collide(hammer(), Pose{{0, 1.0}, {}}, floor, Pose{}, 0.0);
  CHECK(m.separation == doctest::Approx(0.5).epsilon(1e-12));
  CHECK(m.normal.y() == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("a body of parts: its bounds and its radius are its parts'") {
  const sim::collision::Aabb box = sim::collision::bounds(hammer(), Pose{{1, 2}, {}});
  CHECK(box.lower.x() == doctest::Approx(0.8).epsilon(1e-12));
  CHECK(box.upper.x() == doctest::Approx(1.2).epsilon(1e-12));
  CHECK(box.lower.y() == doctest::Approx(1.5).epsilon(1e-12));
  CHECK(box.upper.y() == doctest::Approx(2.7).epsilon(1e-12));
  // the head's corner (0.2, 0.7) is the farthest point from the frame's origin
  CHECK(sim::core::boundingRadius(hammer()) >= Vec2(0.2, 0.7).norm() - 1e-12);
}

TEST_CASE("parts that overlap are found; parts that touch are not") {
  CHECK_FALSE(sim::collision::overlappingPart(hammer(), 1e-9).has_value());
  const Shape overlapping = sim::core::makeCompound(
      {{sim::core::makeBox(1, 1), {}}, {sim::core::makeBox(1, 1), {{2, 0}, {}}}, {sim::core::makeCircle(0.5), {{0.9, 0}, {}}}});
  const std::optional<int> k = sim::collision::overlappingPart(overlapping, 1e-9);
  REQUIRE(k.has_value());
  CHECK(*k == 2);
  CHECK_THROWS_AS(sim::core::makeCompound({{sim::core::makeBox(1, 1), {}}}), std::invalid_argument);
}

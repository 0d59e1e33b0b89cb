#include "sim/world/contact.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim/core/settings.h"

using sim::core::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSides = 300;

// a regular 300-gon of circumradius 1 whose edge 0 faces straight up (+y)
sim::core::Shape manyGon() {
  std::vector<Vec2> v;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2.0 * kPi * i / kSides + kPi / 2.0 - kPi / kSides;
    v.emplace_back(std::cos(a), std::sin(a));
  }
  return sim::core::makePolygon(v);
}

// turned by `steps` of its own symmetry (2π/300 each): the same outline, its vertices renumbered
sim::core::Pose turned(double x, double y, int steps) {
  return {Vec2(x, y), sim::core::Rot::fromAngle(2.0 * kPi * steps / kSides)};
}

// A resting on B, their faces flat together: A's bottom edge is edge (150 − aSteps) mod 300 and
// B's top edge is edge −bSteps mod 300
sim::world::Contact facing(int aSteps, int bSteps, double sink = 0.0) {
  const sim::core::Shape shape = manyGon();
  const double apothem = std::cos(kPi / kSides);
  sim::world::Contact c;
  c.a = 0, c.b = 1;
  c.manifold = sim::collision::collide(shape, turned(0.0, 2.0 * apothem - 0.01 - sink, aSteps), shape, turned(0.0, 0.0, bSteps),
                                       sim::core::settings::kContactMargin);
  return c;
}

}  // namespace

TEST_CASE("two 300-gons face to face: features past index 255 have their own ids, and warm start matches each point to its own") {
  // edges 260 of both, then edges 4 of both: the same geometry, features 256 apart
  sim::world::Contact high = facing(150 - 260 + kSides, -260 + kSides);
  sim::world::Contact low = facing(150 - 4, -4);
  REQUIRE(high.manifold.count == 2);
  REQUIRE(low.manifold.count == 2);
  for (int k = 0; k < 2; ++k) {
    // the two layouts touch at the same places, within round-off
    const Vec2 p = high.manifold.points[k].point;
    CHECK(std::min((p - low.manifold.points[0].point).norm(), (p - low.manifold.points[1].point).norm()) < 1e-9);
    for (int m = 0; m < 2; ++m) CHECK(high.manifold.points[k].id != low.manifold.points[m].id);
  }
  CHECK(high.manifold.points[0].id != high.manifold.points[1].id);

  high.state[0].normalImpulse = 1.0, high.state[0].tangentImpulse = 2.0;
  high.state[1].normalImpulse = 3.0, high.state[1].tangentImpulse = 4.0;

  // other features at the same places: nothing carries over
  sim::world::Contact renumbered = low;
  sim::world::carryImpulses(high, renumbered);
  for (int k = 0; k < 2; ++k) {
    CHECK(renumbered.state[k].normalImpulse == 0.0);
    CHECK(renumbered.state[k].tangentImpulse == 0.0);
  }

  // the same features a step later, A sunk 1 mm deeper: each point gets the impulses of its own
  // previous point, the one above it
  sim::world::Contact same = facing(150 - 260 + kSides, -260 + kSides, 1e-3);
  REQUIRE(same.manifold.count == 2);
  sim::world::carryImpulses(high, same);
  for (int k = 0; k < 2; ++k) {
    const Vec2 p = same.manifold.points[k].point;
    const int own = (p - high.manifold.points[0].point).norm() < (p - high.manifold.points[1].point).norm() ? 0 : 1;
    CHECK((p - high.manifold.points[own].point).norm() < 2e-3);
    CHECK(same.state[k].normalImpulse == high.state[own].normalImpulse);
    CHECK(same.state[k].tangentImpulse == high.state[own].tangentImpulse);
  }
}

#include "sim/collision/time_of_impact.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "sim/collision/collide.h"

using sim::core::Vec2;

namespace {

constexpr double kTolerance = 1e-12;  // m: the gap an impact is found within
constexpr double kTouching = 1e-9;    // m: the touching band at the start

// a body thrown under constant acceleration g, turning at constant ω: x + vτ + ½gτ², θ + ωτ
struct Throw {
  Vec2 x = Vec2::Zero(), v = Vec2::Zero(), g = Vec2::Zero();
  double angle = 0.0, omega = 0.0;
  sim::core::Pose at(double t) const { return {x + t * v + 0.5 * t * t * g, sim::core::Rot::fromAngle(angle + omega * t)}; }
  sim::core::BodyState state(double t) const {
    const sim::core::Pose p = at(t);
    return {p.x, angle + omega * t, v + t * g, omega};
  }
};

struct Pair {
  sim::core::Shape a, b;
  Throw ta, tb;

  double gap(double t) const { return sim::collision::collide(a, ta.at(t), b, tb.at(t), 0.0).separation; }

  // the search over [0, horizon]: the approach bound taken at both ends, as the event method does
  // (under constant acceleration the speeds change linearly, so the ends bound them)
  sim::collision::ToiInput input(double horizon) const {
    sim::collision::ToiInput in;
    in.a = &a, in.b = &b;
    in.motion = [this](double t) { return sim::collision::PosePair{ta.at(t), tb.at(t)}; };
    in.approachBound = std::max(sim::collision::approachBound(a, ta.state(0), b, tb.state(0)),
                                sim::collision::approachBound(a, ta.state(horizon), b, tb.state(horizon)));
    in.horizon = horizon, in.span = horizon, in.tolerance = kTolerance, in.touching = kTouching;
    return in;
  }
  std::optional<double> toi(double horizon) const { return sim::collision::timeOfImpact(input(horizon)); }
};

Pair onFloor(const sim::core::Shape& shape, const Throw& t) {
  Pair p{shape, sim::core::makePlane({0, 1}), t, {}};
  return p;
}

// the gap at an impact: never an overlap beyond the round-off of the poses, and within a few
// tolerances (the search stops when regula falsi's kept gap, which the Illinois step halves, is
// within the tolerance: the true gap there can be twice that, or more after repeated halvings)
void checkImpactGap(const Pair& p, double tau) {
  const double s = p.gap(tau);
  CHECK(s >= -1e-14);
  CHECK(s <= 4.0 * kTolerance);
}

}  // namespace

TEST_CASE("a box falling under gravity onto a plane: the impact at ½ g τ² = the height of its bottom") {
  // a 1 × 1 box dropped from rest with its bottom 1.5 m above the floor, g = 10: τ = √(2·1.5/10)
  Throw fall;
  fall.x = {0.3, 2.0}, fall.g = {0.0, -10.0};
  const Pair p = onFloor(sim::core::makeBox(1.0, 1.0), fall);
  const std::optional<double> tau = p.toi(1.0);
  REQUIRE(tau);
  const double exact = std::sqrt(0.3);
  CHECK(*tau <= exact + 1e-15);
  // the gap closes at 10 τ ≈ 5.5 m/s: a few tolerances of gap are a few 1e-13 s
  CHECK(exact - *tau <= 4.0 * kTolerance / 5.0);
  checkImpactGap(p, *tau);
}

TEST_CASE("two boxes approaching at known speeds: the gap 2 m closes at 3 m/s in 2/3 s") {
  Pair p{sim::core::makeBox(1.0, 1.0), sim::core::makeBox(1.0, 1.0), {}, {}};
  p.ta.v = {2.0, 0.0};
  p.tb.x = {3.0, 0.0}, p.tb.v = {-1.0, 0.0};
  const std::optional<double> tau = p.toi(1.0);
  REQUIRE(tau);
  CHECK(*tau <= 2.0 / 3.0 + 1e-15);
  CHECK(2.0 / 3.0 - *tau <= 4.0 * kTolerance / 3.0);
  checkImpactGap(p, *tau);
}

TEST_CASE("a bullet at a thin wall: found although at the horizon it is past the wall") {
  // a 1 cm bullet at 1000 m/s, 1 m from a 1 cm wall: at the end of 10 ms it is 9 m beyond, its
  // end poses never overlap the wall; conservative advancement still stops at the wall's face
  Pair p{sim::core::makeBox(0.01, 0.01), sim::core::makeBox(0.01, 1.0), {}, {}};
  p.ta.v = {1000.0, 0.0};
  p.tb.x = {1.0, 0.0};
  REQUIRE(p.gap(0.01) > 0.0);
  const std::optional<double> tau = p.toi(0.01);
  REQUIRE(tau);
  // the faces meet after 0.99 m at 1000 m/s
  CHECK(*tau <= 0.99e-3 + 1e-18);
  CHECK(0.99e-3 - *tau <= 4.0 * kTolerance / 1000.0);
  checkImpactGap(p, *tau);
}

TEST_CASE("a spinning bar above a floor: its corner touches when sin θ + 0.05 cos θ = 0.8") {
  // a 2 × 0.1 bar turning about its center at 3 rad/s, the floor 0.8 m below the center: the
  // lowest corner (1, −0.05) is at −(sin θ + 0.05 cos θ) for θ in [0, π/2]
  Throw spin;
  spin.omega = 3.0;
  Pair p{sim::core::makeBox(2.0, 0.1), sim::core::makePlane({0, 1}), spin, {}};
  p.tb.x = {0.0, -0.8};
  const std::optional<double> tau = p.toi(1.0);
  REQUIRE(tau);
  const double theta = std::asin(0.8 / std::sqrt(1.0 + 0.05 * 0.05)) - std::atan(0.05);
  const double exact = theta / 3.0;
  CHECK(*tau <= exact + 1e-15);
  // the corner comes down at 3 (cos θ − 0.05 sin θ) ≈ 1.7 m/s there
  CHECK(exact - *tau <= 4.0 * kTolerance / 1.5);
  checkImpactGap(p, *tau);
}

TEST_CASE("a box resting on the floor and thrown up: no impact leaving, an impact when it comes back") {
  Throw hop;
  hop.x = {0.0, 0.5}, hop.g = {0.0, -10.0};
  SUBCASE("leaving at 1 m/s, back after 2v/g = 0.2 s") {
    hop.v = {0.0, 1.0};
    const Pair p = onFloor(sim::core::makeBox(1.0, 1.0), hop);
    REQUIRE(p.gap(0.0) <= kTouching);
    const std::optional<double> tau = p.toi(1.0);
    REQUIRE(tau);
    CHECK(*tau <= 0.2 + 1e-15);
    // it comes back at 1 m/s
    CHECK(0.2 - *tau <= 4.0 * kTolerance);
    checkImpactGap(p, *tau);
  }
  SUBCASE("leaving at 1 m/s with a horizon of 0.15 s: back only after it") {
    hop.v = {0.0, 1.0};
    CHECK_FALSE(onFloor(sim::core::makeBox(1.0, 1.0), hop).toi(0.15));
  }
  SUBCASE("sliding along the floor without gravity: it stays touching, no impact") {
    hop.g = Vec2::Zero(), hop.v = {2.0, 0.0};
    CHECK_FALSE(onFloor(sim::core::makeBox(1.0, 1.0), hop).toi(1.0));
  }
}

TEST_CASE("no impact: moving apart, passing by, meeting after the horizon, nothing moving") {
  Pair p{sim::core::makeCircle(0.5), sim::core::makeBox(1.0, 1.0), {}, {}};
  p.tb.x = {3.0, 0.0};
  SUBCASE("apart") {
    p.ta.v = {-1.0, 0.0};
    CHECK_FALSE(p.toi(1.0));
  }
  SUBCASE("passing by 1 m above") {
    p.ta.x = {0.0, 1.5}, p.ta.v = {10.0, 0.0};
    CHECK_FALSE(p.toi(1.0));
  }
  SUBCASE("the gap of 2 m closes at 1 m/s, after a horizon of 1.5 s") {
    p.ta.v = {1.0, 0.0};
    CHECK_FALSE(p.toi(1.5));
    CHECK(p.toi(2.5));
  }
  SUBCASE("at rest: the approach bound is zero") {
    CHECK(p.input(1.0).approachBound == 0.0);
    CHECK_FALSE(p.toi(1.0));
  }
}

TEST_CASE("random thrown and spinning pairs: never past the contact, and no earlier contact missed") {
  // boxes, circles and triangles thrown at each other with spin: wherever an impact is returned
  // the gap is within [0, tolerance], and sampled finely before it the pair never overlaps
  std::mt19937_64 rng(1996);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // every draw in its own statement: the order a compiler evaluates arguments in is unspecified
  auto shape = [&](int k) {
    const double w = 0.2 + 0.5 * (u(rng) + 1.0);
    const double h = 0.2 + 0.5 * (u(rng) + 1.0);
    if (k % 3 == 0) return sim::core::makeBox(w, h);
    if (k % 3 == 1) return sim::core::makeCircle(0.5 * w);
    return sim::core::makePolygon({{0.0, 0.0}, {w, 0.1}, {0.2, h}});
  };
  int hits = 0;
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    Pair p;
    p.a = shape(k);
    p.b = shape(k / 3);
    for (Throw* t : {&p.ta, &p.tb}) {
      t->x.y() = 0.5 * u(rng);
      t->angle = 3.0 * u(rng);
      t->omega = 6.0 * u(rng);
      t->v.x() = u(rng);
      t->v.y() = u(rng);
    }
    // A from the left at 2 to 6 m/s, B from the right at up to 2 m/s
    p.ta.x.x() = -1.5, p.ta.v.x() = 4.0 + 2.0 * p.ta.v.x();
    p.tb.x.x() = 1.5, p.tb.v.x() = -1.0 + p.tb.v.x();
    if (k % 2 == 0) p.ta.g = p.tb.g = {0.0, -5.0};
    CAPTURE(k);
    REQUIRE(p.gap(0.0) > kTouching);
    const std::optional<double> tau = p.toi(1.0);
    if (!tau) continue;
    ++hits;
    checkImpactGap(p, *tau);
    worst = std::max(worst, p.gap(*tau) / kTolerance);
    for (int m = 0; m < 1000; ++m) CHECK(p.gap(*tau * m / 1000.0) > 0.0);
  }
  // aimed at each other from 3 m at 2 to 6 m/s: most pairs meet within the second
  MESSAGE(hits << " of 300 random pairs met; worst gap " << worst << " tolerances");
  CHECK(hits > 200);
}

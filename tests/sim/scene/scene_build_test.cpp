// Mass properties as the scene builder composes them (scene_build.cpp): bodies made of parts, and a
// single shape with its center of mass given, against hand-computed values to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/scene/scene_build.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"

namespace {

sim::scene::SceneDef load(const std::string& yaml) { return sim::yaml::loadSceneText(yaml, "inline.yaml"); }
sim::world::World build(const std::string& yaml) { return sim::scene::buildWorld(load(yaml)); }

// one body of the given shape and extra keys
std::string body(const std::string& shape, const std::string& extra = "") {
  return "bodies:\n  - {name: b, shape: " + shape + (extra.empty() ? "" : ", " + extra) + "}\n";
}

constexpr double kRoundOff = 1e-14;

}  // namespace

TEST_CASE("two boxes: mass is the sum, the center the mass-weighted mean, the inertia by the parallel-axis theorem") {
  // a 2 × 1 box at the origin and a 1 × 1 box whose middle is at (1.5, 0), density 1: masses 2 and 1
  const sim::scene::SceneDef def = load(body("{compound: [{box: [2, 1]}, {box: [1, 1], position: [1.5, 0]}]}"));
  const sim::scene::MassProperties m = sim::scene::massProperties(def.bodies[0]);
  CHECK(m.mass == doctest::Approx(3.0).epsilon(kRoundOff));
  // c = (2·0 + 1·1.5)/3 = 0.5
  CHECK(m.centroid.x() == doctest::Approx(0.5).epsilon(kRoundOff));
  CHECK(std::abs(m.centroid.y()) < kRoundOff);
  // I = 2(4 + 1)/12 + 2·0.5² + 1(1 + 1)/12 + 1·1² = 10/12 + 0.5 + 2/12 + 1 = 2.5
  CHECK(m.inertia == doctest::Approx(2.5).epsilon(kRoundOff));
  // the union is a 3 × 1 box: the same numbers from one shape
  const sim::scene::MassProperties one = sim::scene::massProperties(load(body("{box: [3, 1]}")).bodies[0]);
  CHECK(one.mass == doctest::Approx(m.mass).epsilon(kRoundOff));
  CHECK(one.inertia == doctest::Approx(m.inertia).epsilon(kRoundOff));
}

TEST_CASE("a box and a circle, and parts of different densities") {
  // a 1 × 1 box (density 1) and a circle of radius 0.5 at (1, 0) of density 4/π: mass 1 + 1
  const double rho = 4.0 / M_PI;
  const sim::scene::SceneDef def =
      load(body("{compound: [{box: [1, 1]}, {circle: 0.5, position: [1, 0], density: " + std::to_string(rho) + "}]}"));
  const sim::scene::MassProperties m = sim::scene::massProperties(def.bodies[0]);
  const double mc = std::stod(std::to_string(rho)) * M_PI * 0.25;
  CHECK(m.mass == doctest::Approx(1.0 + mc).epsilon(kRoundOff));
  const double c = mc / (1.0 + mc);
  CHECK(m.centroid.x() == doctest::Approx(c).epsilon(kRoundOff));
  // I = 1/6 + 1·c² + ½ mc r² + mc (1 − c)²
  CHECK(m.inertia == doctest::Approx(1.0 / 6.0 + c * c + 0.5 * mc * 0.25 + mc * (1 - c) * (1 - c)).epsilon(kRoundOff));
  // a given mass keeps the parts' proportions: the center stays, the inertia scales with the mass
  const sim::scene::MassProperties heavy = sim::scene::massProperties(
      load(body("{compound: [{box: [1, 1]}, {circle: 0.5, position: [1, 0], density: " + std::to_string(rho) + "}]}", "mass: 6"))
          .bodies[0]);
  CHECK(heavy.mass == 6.0);
  CHECK(heavy.centroid.x() == doctest::Approx(c).epsilon(kRoundOff));
  CHECK(heavy.inertia == doctest::Approx(m.inertia * 6.0 / m.mass).epsilon(kRoundOff));
  // and a given inertia wins
  CHECK(sim::scene::massProperties(
            load(body("{compound: [{box: [1, 1]}, {box: [1, 1], position: [1, 0]}]}", "inertia: 0.7")).bodies[0])
            .inertia == 0.7);
}

TEST_CASE("a turned part: its polygon placed by position and angle") {
  // a 2 × 1 box turned a quarter turn is a 1 × 2 box: the same inertia about its own middle
  const sim::scene::MassProperties turned = sim::scene::massProperties(
      load(body("{compound: [{box: [2, 1], angle: 1.5707963267948966}, {box: [1, 2], position: [1, 0]}]}")).bodies[0]);
  const sim::scene::MassProperties upright =
      sim::scene::massProperties(load(body("{compound: [{box: [1, 2]}, {box: [1, 2], position: [1, 0]}]}")).bodies[0]);
  CHECK(turned.mass == doctest::Approx(upright.mass).epsilon(kRoundOff));
  CHECK(turned.centroid.x() == doctest::Approx(upright.centroid.x()).epsilon(kRoundOff));
  CHECK(turned.inertia == doctest::Approx(upright.inertia).epsilon(kRoundOff));
  // a polygon part written off its own origin: its centroid is where its vertices put it
  const sim::scene::MassProperties tri = sim::scene::massProperties(
      load(body("{compound: [{polygon: [[0, 0], [3, 0], [0, 3]]}, {box: [1, 1], position: [-0.5, 0.5]}]}")).bodies[0]);
  // triangle: area 4.5 at (1, 1); box: area 1 at (−0.5, 0.5)
  CHECK(tri.centroid.x() == doctest::Approx((4.5 * 1.0 + 1.0 * -0.5) / 5.5).epsilon(kRoundOff));
  CHECK(tri.centroid.y() == doctest::Approx((4.5 * 1.0 + 1.0 * 0.5) / 5.5).epsilon(kRoundOff));
}

TEST_CASE("a body of parts is placed by its own frame; its state is its center of mass's") {
  sim::world::World w = build(
      "bodies:\n"
      "  - {name: b, shape: {compound: [{box: [2, 1]}, {box: [1, 1], position: [1.5, 0]}]}, position: [10, 20], "
      "angle: 1.5707963267948966, velocity: [1, 2], angular_velocity: 3}\n");
  const sim::core::Body& b = w.bodies[0];
  // the center (0.5, 0) of the body's frame, turned a quarter, from (10, 20)
  CHECK(b.x.x() == doctest::Approx(10.0).epsilon(kRoundOff));
  CHECK(b.x.y() == doctest::Approx(20.5).epsilon(kRoundOff));
  CHECK(b.v == sim::core::Vec2(1, 2));
  CHECK(b.omega == 3.0);
  CHECK(b.inertia == doctest::Approx(2.5).epsilon(kRoundOff));
}

TEST_CASE("center_of_mass: a single shape whose center of mass is elsewhere") {
  // a unit disk with its center of mass 0.25 from its middle and its inertia about that point given
  sim::world::World w = build(body("{circle: 0.5}", "center_of_mass: [0.25, 0], inertia: 0.1, mass: 2, position: [1, 1]"));
  const sim::core::Body& b = w.bodies[0];
  CHECK(b.x == sim::core::Vec2(1.25, 1.0));
  CHECK(b.mass == 2.0);
  CHECK(b.inertia == 0.1);
  // the disk's middle is 0.25 behind the center of mass: a part placed in the body
  REQUIRE(b.shape.kind == sim::core::ShapeKind::Compound);
  CHECK(b.shape.parts[0].pose.x == sim::core::Vec2(-0.25, 0.0));
  // without an inertia: the uniform disk's about its middle moved to the point, ½ m r² + m d²
  const sim::scene::MassProperties m =
      sim::scene::massProperties(load(body("{circle: 0.5}", "center_of_mass: [0.25, 0], mass: 2")).bodies[0]);
  CHECK(m.inertia == doctest::Approx(0.5 * 2 * 0.25 + 2 * 0.0625).epsilon(kRoundOff));
  // a box with its center of mass given keeps its vertices about that point
  sim::world::World box = build(body("{box: [2, 1]}", "center_of_mass: [0.5, 0], position: [0, 0]"));
  CHECK(box.bodies[0].x == sim::core::Vec2(0.5, 0.0));
  CHECK(box.bodies[0].shape.vertices[0] == sim::core::Vec2(-1.5, -0.5));
}

TEST_CASE("an impulse away from the center of mass: v = j/m and ω = (r′ × j)/I, r′ from the center of mass") {
  // the two-box body (m = 3, I = 2.5, center (0.5, 0) of its frame), struck at the frame point (2, 0.5)
  sim::world::World w = build(
      "bodies:\n"
      "  - {name: b, shape: {compound: [{box: [2, 1]}, {box: [1, 1], position: [1.5, 0]}]}}\n"
      "events:\n"
      "  - {time: 0, body: b, point: [2, 0.5], impulse: [0, 3]}\n");
  w.advanceTo(0.0);
  // r′ = (2, 0.5) − (0.5, 0) = (1.5, 0.5); r′ × j = 1.5·3 − 0.5·0 = 4.5
  CHECK(w.bodies[0].v.x() == 0.0);
  CHECK(w.bodies[0].v.y() == doctest::Approx(1.0).epsilon(kRoundOff));
  CHECK(w.bodies[0].omega == doctest::Approx(4.5 / 2.5).epsilon(kRoundOff));
}

TEST_CASE("a body of parts thrown under gravity: the center on the parabola, ω and the energy constant") {
  // rk4 integrates a constant acceleration exactly: the parabola to round-off
  sim::world::World w = build(
      "world: {gravity: [0, -9.81]}\n"
      "sim: {integrator: rk4, dt: 0.01}\n"
      "bodies:\n"
      "  - {name: hammer, shape: {compound: [{box: [0.1, 1.0]}, {box: [0.4, 0.2], position: [0, 0.6], density: 5}]}, "
      "velocity: [2, 6], angular_velocity: 10}\n");
  const sim::core::Body& b = w.bodies[0];
  const double m = 0.5, I = (0.1 * 1.01 + 0.4 * 0.2) / 12.0 + 0.1 * 0.48 * 0.48 + 0.4 * 0.12 * 0.12;
  CHECK(b.mass == doctest::Approx(m).epsilon(kRoundOff));
  CHECK(b.inertia == doctest::Approx(I).epsilon(kRoundOff));
  const double e0 = 0.5 * m * b.v.squaredNorm() + 0.5 * I * b.omega * b.omega + m * 9.81 * b.x.y();
  for (double t : {0.5, 1.0, 1.5}) {
    w.advanceTo(t);
    CHECK(b.x.x() == doctest::Approx(2.0 * t).epsilon(1e-12));
    CHECK(b.x.y() == doctest::Approx(0.48 + 6.0 * t - 4.905 * t * t).epsilon(1e-12));
    CHECK(b.omega == 10.0);
    CHECK(b.angle == doctest::Approx(10.0 * t).epsilon(1e-12));
    const double e = 0.5 * m * b.v.squaredNorm() + 0.5 * I * b.omega * b.omega + m * 9.81 * b.x.y();
    CHECK(e == doctest::Approx(e0).epsilon(1e-12));
  }
}

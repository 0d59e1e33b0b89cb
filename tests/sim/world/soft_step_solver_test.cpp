// The `soft_step` method (soft_step_solver.cpp): Box2D v3's soft step. Stacks stand at the default
// settings (4 substeps, 30 Hz, damping ratio 10); restitution follows the law from the normal
// velocity before the step; impulses come in equal and opposite pairs, so momentum is kept. Each
// holds in both precisions of the contact solve (sim: precision), a float's round-off in place of
// a double's where the solve's numbers enter.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "sim/world/diagnostics.h"
#include "support/scene_text.h"

namespace {

using namespace scene_text;

const char* kSettings =
    "world: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
    "sim: {collisions: soft_step, dt: 0.016666666666666667}\n"
    "bodies:\n"
    "  - {name: ground, shape: {box: [80, 1]}, static: true, position: [0, -0.5]}\n";

// Box2D's pyramid of base 20 (pyramid.yaml): touching rows, or its testbed's dropped rows
// (y = 0.75 + 1.25 r); the rest pose of box j of row r is (−7 + 0.5625 r + 1.125 j, 0.5 + r)
struct Pile {
  std::string yaml;
  std::vector<sim::core::Vec2> rest;  // per body, the ground first
};

Pile pyramid(bool dropped) {
  Pile p{kSettings, {sim::core::Vec2(0, -0.5)}};
  for (int r = 0; r < 20; ++r)
    for (int j = 0; j < 20 - r; ++j) {
      const double x = -7.0 + 0.5625 * r + 1.125 * j;
      p.yaml += "  - {name: b" + std::to_string(r) + "_" + std::to_string(j) +
                ", shape: {box: [1, 1]}, position: " + vec(x, dropped ? 0.75 + 1.25 * r : 0.5 + r) + "}\n";
      p.rest.emplace_back(x, 0.5 + r);
    }
  return p;
}

// how far the farthest body ends from its rest pose, and the fastest body (its corners included)
struct Held {
  double offRest = 0.0, fastest = 0.0;
};

// the scene with soft_step's contact solve in `precision` (double, the default, or float)
std::string solvedIn(std::string yaml, const std::string& precision) {
  const std::string method = "collisions: soft_step";
  const size_t at = yaml.find(method);
  REQUIRE(at != std::string::npos);
  return yaml.insert(at + method.size(), ", precision: " + precision);
}

const char* const kPrecisions[] = {"double", "float"};

Held runPile(const std::string& yaml, const std::vector<sim::core::Vec2>& rest, double seconds) {
  sim::world::World w = build(yaml);
  REQUIRE(w.collisions() == sim::core::CollisionMethod::SoftStep);
  w.advanceTo(seconds);
  Held h;
  for (size_t i = 1; i < w.bodies.size(); ++i) {
    const sim::core::Body& b = w.bodies[i];
    REQUIRE(sim::core::isFinite(b.x));
    h.offRest = std::max(h.offRest, (b.x - rest[i]).norm());
    h.fastest = std::max(h.fastest, b.v.norm() + 0.5 * std::abs(b.omega));
  }
  return h;
}

}  // namespace

// Measured: touching 0.034 m, dropped 0.045 m off the rest pose (the soft contacts give:
// 20 layers each a little under the load), at rest; Box2D 2.4 on the dropped one: 0.068 m in x.
TEST_CASE("soft_step: Box2D's 20-base pyramid stands, touching or dropped: every box within 5 cm of its rest pose, at rest") {
  for (const std::string precision : kPrecisions)
    for (bool dropped : {false, true}) {
      CAPTURE(precision);
      CAPTURE(dropped);
      const Pile p = pyramid(dropped);
      const Held h = runPile(solvedIn(p.yaml, precision), p.rest, 10.0);
      MESSAGE("soft_step (" << precision << ") pyramid " << std::string(dropped ? "dropped" : "touching")
                            << ": farthest from rest " << h.offRest << " m, fastest " << h.fastest << " m/s");
      CHECK(h.offRest < 0.05);
      CHECK(h.fastest < 0.01);
    }
}

TEST_CASE("soft_step: a two-level house of cards stands (card_house.yaml)") {
  // cards 0.4 m × 2 mm leaning at ±25° in pairs, a flat card bridging the two lower pairs
  const double h = 0.2, lean = 25.0 * 3.14159265358979323846 / 180.0;
  std::string yaml =
      "world: {gravity: [0, -10], friction: 0.7, restitution: 0}\nsim: {collisions: soft_step, dt: 0.016666666666666667}\n"
      "bodies:\n  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  std::vector<sim::core::Vec2> rest{sim::core::Vec2::Zero()};
  auto card = [&](const std::string& name, double x, double y, double angle) {
    yaml += "  - {name: " + name + ", shape: {box: [0.002, 0.4]}, position: " + vec(x, y) + ", angle: " + num(angle) + "}\n";
    rest.emplace_back(x, y);
  };
  const double y0 = h - 0.02, y1 = y0 + 2 * h - 0.03;
  card("flat", 0.25, y0 + h - 0.015, 0.5 * 3.14159265358979323846);
  card("l1", 0.0, y0, -lean), card("r1", 0.175, y0, lean), card("l2", 0.35, y0, -lean), card("r2", 0.525, y0, lean);
  card("l3", 0.175, y1, -lean), card("r3", 0.35, y1, lean);
  for (const std::string precision : kPrecisions) {
    CAPTURE(precision);
    const Held held = runPile(solvedIn(yaml, precision), rest, 10.0);
    MESSAGE("soft_step (" << precision << ") card house: farthest from its start " << held.offRest << " m, fastest "
                          << held.fastest << " m/s");
    CHECK(held.offRest < 0.02);
    CHECK(held.fastest < 0.01);
  }
}

TEST_CASE("soft_step: restitution from the normal velocity before the step, at every impact") {
  // a ball dropped on a floor at each coefficient: each impact leaves at −e times its arrival speed
  // (the restitution pass is the last to act on the point; in doubles in both precisions, from the
  // lever arms the solve used, so the law holds to a double's round-off)
  for (const std::string precision : kPrecisions)
    for (double e : {0.0, 0.3, 0.8, 1.0}) {
      CAPTURE(precision);
      CAPTURE(e);
      sim::world::World w = build(solvedIn("world: {gravity: [0, -10], restitution: " + num(e) +
                                               "}\nsim: {collisions: soft_step, dt: 0.01}\nbodies:\n"
                                               "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
                                               "  - {name: ball, shape: {circle: 0.2}, position: [0, 2]}\n",
                                           precision));
      w.advanceTo(3.0);
      REQUIRE(!w.impacts.empty());
      for (const sim::world::ImpactRecord& r : w.impacts) {
        CAPTURE(r.t);
        CHECK(r.vnBefore < -1.0);
        CHECK(r.vnAfter == doctest::Approx(-e * r.vnBefore).epsilon(1e-9));
      }
    }
}

// In floats each impulse reaches the two bodies' velocities rounded to a float (a relative 6e-8
// each), so momentum is kept to that round-off times the impulses, not to a double's
TEST_CASE("soft_step: momentum is kept in free-space impacts") {
  for (const std::string precision : kPrecisions) {
    CAPTURE(precision);
    const double tolerance = precision == "float" ? 1e-6 : 1e-9;
    std::mt19937_64 rng(77);
    size_t impacts = 0;
    double worst = 0.0;
    for (int k = 0; k < 10; ++k) {
      const std::string yaml = "world: {restitution: 0.5, friction: 0.3}\nsim: {collisions: soft_step, dt: 0.005}\nbodies:\n" +
                               scene_text::randomBody(rng, "a", -2.0, 2.0, 1.0) +
                               scene_text::randomBody(rng, "b", 2.0, -0.5, 0.5);
      CAPTURE(yaml);
      sim::world::World w = build(solvedIn(yaml, precision));
      const sim::core::Vec2 p0 = sim::world::linearMomentum(w);
      w.advanceTo(4.0);
      impacts += w.impacts.size();
      const double error = (sim::world::linearMomentum(w) - p0).norm() / std::max(1.0, p0.norm());
      worst = std::max(worst, error);
      CHECK(error <= tolerance);
    }
    MESSAGE("soft_step (" << precision << "), random pairs: " << impacts << " impacts, momentum kept to " << worst);
    CHECK(impacts >= 5);
  }
}

TEST_CASE("soft_step: a resting contact gives g/ω², ω = 2π · 2 · min(contact_hertz, substep rate / 4) against a static body") {
  // a ball on the ground: at rest the warm-started impulse m g h per substep is what the soft
  // constraint's push gives, a3·λ = m·a2·a3·(ω/a1)·s, so the depth s = g/ω² (Catto's soft step)
  const double pi = std::acos(-1.0);
  // (a plain pair, not a structured binding: clang 14 cannot capture a binding in CAPTURE's lambda)
  for (const std::pair<double, int>& setting : std::vector<std::pair<double, int>>{{30, 4}, {10, 4}, {1000, 4}, {1000, 8}}) {
    const double hertz = setting.first;
    const int substeps = setting.second;
    CAPTURE(hertz);
    CAPTURE(substeps);
    const std::string yaml =
        "world: {gravity: [0, -10], restitution: 0}\n"
        "sim: {collisions: soft_step, dt: 0.016666666666666667, substeps: " +
        std::to_string(substeps) + ", contact_hertz: " + num(hertz) +
        "}\n"
        "bodies:\n"
        "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
        "  - {name: ball, shape: {circle: 0.5}, mass: 2, position: [0, 0.5]}\n";
    const double capped = std::min(hertz, 0.25 * 60.0 * substeps);
    const double omega = 2.0 * pi * 2.0 * capped;
    sim::world::World w = build(yaml);
    w.advanceTo(5.0);
    CHECK(0.5 - w.bodies[1].x.y() == doctest::Approx(10.0 / (omega * omega)).epsilon(1e-9));
    CHECK(std::abs(w.bodies[1].v.y()) < 1e-12);
    // in floats the depth is the separation of two lever arms of 0.5 m, each rounded to a float
    // (a unit in the last place is 6e-8 m): measured 1.6e-8 m off at 30 Hz, 1.0e-8 m at 1000 Hz
    sim::world::World f = build(solvedIn(yaml, "float"));
    f.advanceTo(5.0);
    CHECK(std::abs(0.5 - f.bodies[1].x.y() - 10.0 / (omega * omega)) < 6e-8);
    CHECK(std::abs(f.bodies[1].v.y()) < 1e-12);
  }
}

TEST_CASE("soft_step: precision is read, double by default, double or float only") {
  const std::string ball = "bodies: [{name: a, shape: {circle: 1}}]\n";
  CHECK(build("sim: {collisions: soft_step}\n" + ball).def().precision == sim::world::Precision::Double);
  CHECK(build("sim: {collisions: soft_step, precision: float}\n" + ball).def().precision == sim::world::Precision::Float);
  CHECK(build("sim: {collisions: soft_step, precision: double}\n" + ball).def().precision == sim::world::Precision::Double);
  CHECK_THROWS_WITH_AS(build("sim: {collisions: soft_step, precision: half}\n" + ball),
                       doctest::Contains("inline.yaml:1:41: unknown precision 'half'; choose one of: double, float"),
                       std::exception);
}

TEST_CASE("soft_step: contact_hertz is read, positive only") {
  CHECK(build(std::string(kSettings) + "  - {name: box, shape: {box: [1, 1]}, position: [0, 0.5]}\n").def().contactHertz == 30.0);
  const std::string stiff = "sim: {collisions: soft_step, contact_hertz: 120}\nbodies: [{name: a, shape: {circle: 1}}]\n";
  CHECK(build(stiff).def().contactHertz == 120.0);
  CHECK_THROWS_WITH_AS(build("sim: {contact_hertz: 0}\nbodies: [{name: a, shape: {circle: 1}}]\n"),
                       doctest::Contains("contact_hertz"), std::exception);
}

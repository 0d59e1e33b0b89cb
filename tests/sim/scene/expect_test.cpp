#include "sim/scene/expect.h"

#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "sim/yaml/scene_yaml.h"

namespace {

// the ball's expected height at t = 2 is `y`
std::string scene(const char* y) {
  std::ostringstream o;
  o << R"(
duration: 2
world: {gravity: [0, -10]}
sim: {integrator: midpoint, dt: 0.01}
bodies: [{name: ball, shape: {circle: 0.5}, mass: 2, velocity: [1, 10]}]
expect:
  - {time: 1, body: ball, position: [1, 5], velocity: [1, 0], tolerance: 1e-12}
  - {time: 2, body: ball, position: [2, )"
    << y << R"(], tolerance: 1e-12}
  - {time: 2, total_energy: 101, momentum: [2, -20], tolerance: 1e-12}
)";
  return o.str();
}

}  // namespace

TEST_CASE("expect entries pass on the closed form and fail, with the error, when it is wrong") {
  const std::string good = scene("0"), bad = scene("0.001");

  const auto results = sim::scene::runExpects(sim::yaml::loadSceneText(good, "inline.yaml"));
  REQUIRE(results.size() == 5);
  for (const auto& r : results) CHECK(r.passed());
  CHECK(results[0].quantity == "ball.position");
  CHECK(results[3].quantity == "total_energy");
  CHECK(results[4].quantity == "momentum");

  const auto failed = sim::scene::runExpects(sim::yaml::loadSceneText(bad, "inline.yaml"));
  CHECK_FALSE(failed[2].passed());
  CHECK(failed[2].error == doctest::Approx(0.001).epsilon(1e-9));
  CHECK(failed[2].time == 2.0);
}

namespace {

// a mass on a spring (m = 1, k = 4: ω = 2 rad/s, amplitude A = 1 m, E = 2 J) for 5 s at h = 0.01
// (hω = 0.02), and the entry that its energy never rises by more than 0.05 J
std::string springUnder(const char* integrator) {
  return std::string("duration: 5\nsim: {integrator: ") + integrator +
         ", dt: 0.01}\nbodies: [{name: mass, shape: {circle: 0.1}, mass: 1, position: [1, 0]}]\n"
         "forces: [{type: spring, body: mass, anchor: [0, 0], stiffness: 4}]\n"
         "expect: [{energy_never_rises: true, tolerance: 0.05}]\n";
}

}  // namespace

TEST_CASE(
    "energy_never_rises: explicit Euler on a spring fails it, at the first step past the tolerance; symplectic Euler passes") {
  // explicit Euler multiplies the energy by 1 + (hω)² every step: 2 J × (1.0004ⁿ − 1) passes 0.05 J
  // at n = ln(1.025)/ln(1.0004) = 61.74, so at the 62nd step, t = 0.62 s
  const auto gains = sim::scene::runExpects(sim::yaml::loadSceneText(springUnder("explicit_euler"), "inline.yaml"));
  REQUIRE(gains.size() == 1);
  CHECK_FALSE(gains[0].passed());
  CHECK(gains[0].time == doctest::Approx(0.62).epsilon(1e-12));
  CHECK(gains[0].error == doctest::Approx(2.0 * (std::pow(1.0004, 62) - 1.0)).epsilon(1e-9));
  CHECK(gains[0].quantity == "energy_never_rises (rose in free motion: the integrator's)");
  // symplectic Euler keeps ½v² + ½ω²x² − ½hω²xv, so its energy swings by ±¼hω³A² = ±0.02 J and
  // comes back: it rises 0.04 J above its lowest, within the tolerance
  const auto holds = sim::scene::runExpects(sim::yaml::loadSceneText(springUnder("symplectic_euler"), "inline.yaml"));
  REQUIRE(holds.size() == 1);
  CHECK(holds[0].passed());
  CHECK(holds[0].time == 5.0);
  CHECK(holds[0].error == doctest::Approx(0.04).epsilon(0.01));
}

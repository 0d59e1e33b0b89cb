#include "sim/scene/expect.h"

#include <doctest/doctest.h>

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

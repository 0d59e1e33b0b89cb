// What a named collision method leaves out of what the scene asks for, said at its key
// (model_warnings.cpp).
#include <doctest/doctest.h>

#include <string>

#include "sim/scene/model_warnings.h"
#include "sim/yaml/scene_yaml.h"

namespace {

std::vector<sim::scene::ModelWarning> warningsOf(const std::string& yaml) {
  return sim::scene::modelWarnings(sim::yaml::loadSceneText(yaml, "inline.yaml"));
}

const std::string kBodies =
    "bodies:\n"
    "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
    "  - {name: crate, shape: {box: [1, 1]}, position: [0, 2], friction: 0.4}\n";

}  // namespace

TEST_CASE("a named method without sliding friction is warned at its key when the scene names friction under a load") {
  for (const std::string method : {"event", "isolated", "none"}) {
    CAPTURE(method);
    const auto w = warningsOf("world: {gravity: [0, -9.81]}\nsim: {collisions: " + std::string(method) + "}\n" + kBodies);
    REQUIRE(w.size() == 1);
    CHECK(w[0].setting == "collisions");
    CHECK(w[0].value == method);
    // at the value of `collisions:` on line 2
    CHECK(w[0].loc.line == 2);
    CHECK(w[0].loc.column == 19);
    CHECK(w[0].message.find("sliding friction") != std::string::npos);
    CHECK(w[0].message.find("'sequential'") != std::string::npos);
  }
  // none models no impacts either
  CHECK(warningsOf("world: {gravity: [0, -9.81]}\nsim: {collisions: none}\n" + kBodies)[0].message.find("friction at impacts") !=
        std::string::npos);
}

TEST_CASE("no warning where the method models what the scene asks, or where the scene asks for no friction") {
  for (const char* method : {"sequential", "soft_step"})
    CHECK(warningsOf("world: {gravity: [0, -9.81]}\nsim: {collisions: " + std::string(method) + "}\n" + kBodies).empty());
  // auto is never warned: it picks what the scene needs and switches when contact persists
  CHECK(warningsOf("world: {gravity: [0, -9.81]}\n" + kBodies).empty());
  // frictionless: event models the notes' impacts exactly
  CHECK(warningsOf("world: {gravity: [0, -9.81]}\nsim: {collisions: event}\nbodies:\n"
                   "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
                   "  - {name: ball, shape: {circle: 0.5}, position: [0, 2]}\n")
            .empty());
  // friction without a load: event's frictional impacts are all it takes
  CHECK(warningsOf("sim: {collisions: event}\n" + kBodies).empty());
}

TEST_CASE("soft_step with another integrator than its own is warned at `integrator:`") {
  const auto w = warningsOf("sim: {collisions: soft_step, integrator: rk4}\n" + kBodies);
  REQUIRE(w.size() == 1);
  CHECK(w[0].setting == "integrator");
  CHECK(w[0].value == "rk4");
  CHECK(w[0].loc.line == 1);
  CHECK(w[0].loc.column == 42);
  CHECK(w[0].message.find("symplectic Euler") != std::string::npos);
  CHECK(warningsOf("sim: {collisions: soft_step, integrator: symplectic_euler}\n" + kBodies).empty());
  // every other method moves the bodies by the scene's integrator, its contacts right with each
  CHECK(warningsOf("sim: {collisions: sequential, integrator: rk4}\n" + kBodies).empty());
}

// The `none` method and the free motion every fixed-step method starts from: the integrator over
// a step, with the timed forces of the step.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"

namespace {

sim::world::World build(const char* yaml) { return sim::scene::buildWorld(sim::yaml::loadSceneText(yaml, "inline.yaml")); }

}  // namespace

TEST_CASE("a force switching off at a step's end acts at all of that step's rk4 stages: v = f t / m exactly") {
  // f = (0, 1) N on 1 kg for 1 s with rk4: a constant force is integrated exactly, so v(1) = 1 m/s
  // and y(1) = ½ m; were the force off at RK4's last stage of the last step (t = 1), v would fall
  // short by h/6
  sim::world::World w = build(R"(
sim: {integrator: rk4, dt: 0.01}
bodies: [{name: puck, shape: {circle: 0.1}, mass: 1}]
forces: [{type: force, body: puck, point: [0, 0], force: [0, 1], until: 1}]
)");
  w.advanceTo(1.0);
  CHECK(std::abs(w.bodies[0].v.y() - 1.0) <= 1e-12);
  CHECK(std::abs(w.bodies[0].x.y() - 0.5) <= 1e-12);
  w.advanceTo(2.0);
  CHECK(std::abs(w.bodies[0].v.y() - 1.0) <= 1e-12);
  CHECK(std::abs(w.bodies[0].x.y() - 1.5) <= 1e-12);
}

TEST_CASE("a force switching on inside a step acts from the switch on: the step is split there") {
  // on at 0.005 s, inside the first 0.01 s step: v(1) = 0.995 m/s, y(1) = ½ (0.995)² m
  sim::world::World w = build(R"(
sim: {integrator: midpoint, dt: 0.01}
bodies: [{name: puck, shape: {circle: 0.1}, mass: 1}]
forces: [{type: force, body: puck, point: [0, 0], force: [0, 1], from: 0.005}]
)");
  w.advanceTo(1.0);
  CHECK(std::abs(w.bodies[0].v.y() - 0.995) <= 1e-12);
  CHECK(std::abs(w.bodies[0].x.y() - 0.5 * 0.995 * 0.995) <= 1e-12);
}

TEST_CASE("none: bodies pass through each other untouched, and no contact or impact is recorded") {
  sim::world::World w = build(R"(
sim: {collisions: none, dt: 0.01}
bodies:
  - {name: left, shape: {box: [1, 1]}, position: [-2, 0], velocity: [2, 0], angular_velocity: 1}
  - {name: right, shape: {circle: 0.5}, position: [2, 0], velocity: [-2, 0]}
)");
  w.advanceTo(2.0);
  // they crossed at t = 0.75 s and went on as if alone
  CHECK(std::abs(w.bodies[0].x.x() - 2.0) <= 1e-12);
  CHECK(std::abs(w.bodies[1].x.x() + 2.0) <= 1e-12);
  CHECK(w.bodies[0].v.x() == 2.0);
  CHECK(w.bodies[0].omega == 1.0);
  CHECK(w.bodies[1].v.x() == -2.0);
  CHECK(w.impacts.empty());
  CHECK(w.contacts.empty());
}

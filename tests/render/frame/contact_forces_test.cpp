// The forces a body's contacts put on it (contact_forces.cpp): the stack solvers' impulses over the
// last step divided by it. A box sliding on a rough floor feels N = m g up and μ N against its motion,
// under the sequential solver and under soft_step (whose impulses are a substep's); the event method,
// which applies impacts, gives none.
#include "render/frame/contact_forces.h"

#include <doctest/doctest.h>

#include "sim/scene/scene_build.h"
#include "support/drawn_scene.h"

namespace {

// a 2 kg box at 4 m/s on a floor with μ = 0.5 under g = 10: N = 20 N, friction 10 N until it stops
std::string slide(const std::string& method) {
  return "duration: 1.2\n"
         "world: {gravity: [0, -10], friction: 0.5, restitution: 0}\n"
         "sim: {collisions: " +
         method +
         ", dt: 0.01}\n"
         "bodies:\n"
         "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
         "  - {name: box, shape: {box: [1, 0.5]}, mass: 2, position: [0, 0.25], velocity: [4, 0]}\n";
}

std::vector<render::frame::ContactForce> forcesAt(const std::string& yaml, double t) {
  sim::world::World world = sim::scene::buildWorld(drawn_scene::load(yaml).model);
  world.advanceTo(t);
  return render::frame::contactForcesOn(world, 1);
}

}  // namespace

TEST_CASE("a sliding box: the floor's normal force m g and the friction μ N against its motion") {
  for (const std::string method : {"sequential", "soft_step"}) {
    CAPTURE(method);
    const std::vector<render::frame::ContactForce> f = forcesAt(slide(method), 0.3);
    REQUIRE(f.size() == 1);
    CHECK(f[0].normal.x() == doctest::Approx(0.0).epsilon(1e-6));
    CHECK(f[0].normal.y() == doctest::Approx(20.0).epsilon(1e-3));
    CHECK(f[0].friction.x() == doctest::Approx(-10.0).epsilon(1e-3));
    // where the normal impulses are centred: on the floor, under the box
    CHECK(f[0].point.y() == doctest::Approx(0.0).epsilon(1e-3));
    CHECK(std::abs(f[0].point.x() - (4 * 0.3 - 2.5 * 0.09)) < 0.5);
  }
  // at rest under the sequential solver the friction has nothing to hold
  const std::vector<render::frame::ContactForce> rest = forcesAt(slide("sequential"), 1.2);
  REQUIRE(rest.size() == 1);
  CHECK(rest[0].normal.y() == doctest::Approx(20.0).epsilon(1e-3));
  CHECK(std::abs(rest[0].friction.x()) < 1e-9);
}

TEST_CASE("the floor feels the box's forces the other way; the event method gives none") {
  sim::world::World world = sim::scene::buildWorld(drawn_scene::load(slide("sequential")).model);
  world.advanceTo(0.3);
  const std::vector<render::frame::ContactForce> floor = render::frame::contactForcesOn(world, 0);
  REQUIRE(floor.size() == 1);
  CHECK(floor[0].normal.y() == doctest::Approx(-20.0).epsilon(1e-3));
  CHECK(floor[0].friction.x() == doctest::Approx(10.0).epsilon(1e-3));
  const std::string ball =
      "duration: 1\nworld: {gravity: [0, -10]}\nsim: {collisions: event}\nbodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: ball, shape: {circle: 0.5}, position: [0, 2]}\n";
  CHECK(forcesAt(ball, 1.0).empty());
}

#include "sim/world/diagnostics.h"

#include <doctest/doctest.h>

#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"

TEST_CASE("energies and momenta of known states") {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
world: {gravity: [0, -10]}
bodies:
  - {name: a, shape: {circle: 1}, mass: 2, inertia: 3, position: [1, 2], velocity: [3, -1], angular_velocity: 2}
  - {name: b, shape: {box: [1, 1]}, mass: 1, inertia: 0.5, position: [-1, 0], velocity: [0, 4], angular_velocity: -1}
  - {name: wall, shape: {box: [1, 10]}, static: true, position: [5, 0]}
forces:
  - {type: spring, body: a, point: [0, 0], body2: b, point2: [0, 0], stiffness: 8, rest_length: 1}
)",
                                                      "inline.yaml");
  const sim::world::World w = sim::scene::buildWorld(def);
  // ½ m v² + ½ I ω²
  CHECK(sim::world::kineticEnergy(w.bodies[0]).translational == 10.0);
  CHECK(sim::world::kineticEnergy(w.bodies[0]).rotational == 6.0);
  CHECK(sim::world::kineticEnergy(w.bodies[1]).total() == 8.25);
  CHECK(sim::world::kineticEnergy(w.bodies[2]).total() == 0.0);
  const sim::world::Energy e = sim::world::energy(w);
  CHECK(e.kinetic == 24.25);
  // gravity: m g y = 2·10·2 + 1·10·0; spring: ½·8·(|(2, 2)| − 1)²
  const double stretch = std::sqrt(8.0) - 1.0;
  CHECK(e.potential == doctest::Approx(40.0 + 4.0 * stretch * stretch).epsilon(1e-15));
  CHECK(e.total() == doctest::Approx(e.kinetic + e.potential));
  CHECK(sim::world::linearMomentum(w) == sim::core::Vec2(6, 2));
  // Σ x × m v + I ω = (1, 2) × (6, −2) + 6 + (−1, 0) × (0, 4) − 0.5
  CHECK(sim::world::angularMomentum(w) == doctest::Approx((-2.0 - 12.0) + 6.0 + (-4.0) - 0.5));
}

TEST_CASE("free flight conserves momentum, angular momentum about the origin and energy exactly") {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
sim: {integrator: symplectic_euler, dt: 0.01}
bodies:
  - {name: a, shape: {polygon: [[0, 0], [2, 0], [0, 1]]}, position: [1, 2], velocity: [3, -1], angular_velocity: 2}
)",
                                                      "inline.yaml");
  sim::world::World w = sim::scene::buildWorld(def);
  const double l0 = sim::world::angularMomentum(w), e0 = sim::world::energy(w).total();
  const sim::core::Vec2 p0 = sim::world::linearMomentum(w);
  w.advanceTo(3.0);
  CHECK((sim::world::linearMomentum(w) - p0).norm() < 1e-14);
  CHECK(sim::world::angularMomentum(w) == doctest::Approx(l0).epsilon(1e-13));
  CHECK(sim::world::energy(w).total() == doctest::Approx(e0).epsilon(1e-14));
}

// The table of what each collision method models (method_models.h), held to what the methods do:
// every phenomenon a row claims is shown on a scene, and what `event` leaves out is shown missing.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/world/method_models.h"
#include "support/scene_text.h"

namespace {

using scene_text::build;
using scene_text::num;
using sim::core::CollisionMethod;
using sim::core::Phenomenon;

const sim::core::Integrator kIntegrators[] = {sim::core::Integrator::ExplicitEuler, sim::core::Integrator::SymplecticEuler,
                                              sim::core::Integrator::Midpoint, sim::core::Integrator::Rk4};

std::string header(CollisionMethod m, sim::core::Integrator integrator, double friction) {
  return "world: {gravity: [0, -9.81], friction: " + num(friction) +
         "}\nsim: {collisions: " + std::string(sim::core::collisionMethodName(m)) +
         ", integrator: " + std::string(sim::core::integratorName(integrator)) +
         ", dt: 0.01}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
}

}  // namespace

// under every integrator a scene may name: a method that moves the bodies by its own (soft_step)
// holds them too, the scene's integrator unused (and warned of: model_warnings.h)
TEST_CASE("every method that claims resting contact, stacks and sliding friction shows them, under every integrator") {
  for (const sim::core::MethodModel& row : sim::world::kMethodModels)
    for (const sim::core::Integrator integrator : kIntegrators) {
      CAPTURE(sim::core::collisionMethodName(row.method));
      CAPTURE(sim::core::integratorName(integrator));
      if (sim::core::has(row.models, Phenomenon::RestingContact)) {
        // a box put on the floor stays there: still, and within the contact slop of its height
        sim::world::World w =
            build(header(row.method, integrator, 0.5) + "  - {name: box, shape: {box: [1, 1]}, position: [0, 0.5]}\n");
        w.advanceTo(3.0);
        CHECK(w.bodies[1].v.norm() <= 1e-3);
        CHECK(std::abs(w.bodies[1].x.y() - 0.5) <= sim::core::settings::kLinearSlop);
      }
      if (sim::core::has(row.models, Phenomenon::Stacks)) {
        // five boxes on each other stay within a slop of their heights each
        std::string s = header(row.method, integrator, 0.5);
        for (int i = 0; i < 5; ++i)
          s += "  - {name: b" + std::to_string(i) + ", shape: {box: [1, 1]}, position: [0, " + num(0.5 + i) + "]}\n";
        sim::world::World w = build(s);
        w.advanceTo(3.0);
        for (int i = 0; i < 5; ++i)
          CHECK(std::abs(w.bodies[1 + i].x.y() - (0.5 + i)) <= sim::core::settings::kLinearSlop * (i + 1));
      }
      if (sim::core::has(row.models, Phenomenon::SlidingFriction)) {
        // a box launched at 2 m/s along the floor stops near v²/(2μg) = 0.68 m
        sim::world::World w = build(header(row.method, integrator, 0.3) +
                                    "  - {name: box, shape: {box: [1, 0.5]}, position: [0, 0.25], velocity: [2, 0]}\n");
        w.advanceTo(2.0);
        CHECK(w.bodies[1].v.norm() <= 1e-3);
        CHECK(w.bodies[1].x.x() == doctest::Approx(4.0 / (2 * 0.3 * 9.81)).epsilon(0.05));
      }
    }
}

TEST_CASE("what event leaves out is missing: a box that lands on a rough floor slides on without friction") {
  REQUIRE_FALSE(sim::world::models(CollisionMethod::Event, Phenomenon::SlidingFriction));
  // dropped flat from 1 cm above the floor's contact margin with 2 m/s along it: friction at the
  // impact takes a little of its speed, then its resting contact has none
  sim::world::World w = build(header(CollisionMethod::Event, sim::core::Integrator::SymplecticEuler, 0.5) +
                              "  - {name: box, shape: {box: [1, 0.5]}, position: [0, 0.27], velocity: [2, 0]}\n");
  w.advanceTo(2.0);
  REQUIRE_FALSE(w.resting.empty());
  CHECK(w.bodies[1].v.x() > 1.0);
}

TEST_CASE("auto's choice is the least method whose row has what the scene needs") {
  CHECK(sim::world::leastMethodFor(0) == CollisionMethod::None);
  CHECK(sim::world::leastMethodFor(sim::core::bit(Phenomenon::IsolatedImpacts)) == CollisionMethod::Event);
  CHECK(sim::world::leastMethodFor(Phenomenon::IsolatedImpacts | Phenomenon::FrictionAtImpacts) == CollisionMethod::Event);
  CHECK(sim::world::leastMethodFor(Phenomenon::IsolatedImpacts | Phenomenon::RestingContact) == CollisionMethod::Sequential);
  CHECK(sim::world::leastMethodFor(sim::core::bit(Phenomenon::Stacks)) == CollisionMethod::Sequential);
  CHECK(sim::core::phenomenaText(Phenomenon::SlidingFriction | Phenomenon::Stacks) == "sliding friction, stacks");
  CHECK_THROWS_AS((void)sim::world::methodModel(CollisionMethod::Auto), std::logic_error);
}

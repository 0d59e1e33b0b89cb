// The 3D `sequential` method (sequential3d.cpp): a ball that slides then rolls as the closed form
// says, a die that tumbles onto the floor and comes to rest on a face, and resting contact right
// under every integrator.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/world3d/diagnostics.h"
#include "sim/world3d/energy_ledger3d.h"
#include "sim/world3d/world.h"
#include "support/redefined.h"

using namespace sim::world3d;
using sim::core::CollisionMethod;

namespace {
constexpr double kG = 9.81;
const Integrator kIntegrators[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Midpoint, Integrator::Rk4,
                                   Integrator::Splitting};

World onFloor(double friction, Integrator integrator = Integrator::Splitting) {
  WorldDef def;
  def.planes.push_back({Vec3::Zero(), Vec3::UnitZ(), 0.5, friction, true});
  def.forces.gravity = Vec3(0, 0, -kG);
  def.integrator = integrator;
  return World(def);
}
}  // namespace

TEST_CASE("a ball launched without spin slides, then rolls at 5/7 of its speed from t = 2 v₀/(7 μ g), ω = v/r") {
  const double v0 = 2.0, mu = 0.3, r = 0.1;
  for (const Integrator integrator : kIntegrators) {
    CAPTURE(kIntegratorNames.name(integrator));
    World w = onFloor(mu, integrator);
    Body ball = makeBody(makeSphere(r), 1.0 / (4.0 / 3.0 * M_PI * r * r * r));
    ball.friction = mu;
    ball.x = Vec3(0, 0, r), ball.v = Vec3(v0, 0, 0);
    w.bodies.push_back(ball);
    // touching under gravity at the start: auto chooses sequential
    w.start();
    REQUIRE(w.collisions() == CollisionMethod::Sequential);
    const double rolls = 2 * v0 / (7 * mu * kG);
    // still sliding a step before, rolling from a step after
    w.advanceTo(rolls - 2 * w.def().dt);
    const Body& b = w.bodies[0];
    CHECK(b.v.x() - b.omega.y() * r > 1e-3);
    w.advanceTo(1.0);
    CHECK(b.v.x() == doctest::Approx(5.0 / 7.0 * v0).epsilon(1e-12));
    CHECK(b.omega.y() == doctest::Approx(5.0 / 7.0 * v0 / r).epsilon(1e-12));
    CHECK(std::abs(b.v.z()) <= 1e-12);
    CHECK(std::abs(b.x.z() - r) <= 1e-12);
  }
}

TEST_CASE("a die thrown tumbling onto the floor comes to rest on a face, its energy never rising past a few mJ") {
  World w = onFloor(0.5);
  Body die = makeBody(makeBox(Vec3(0.2, 0.2, 0.2)), 125.0);
  die.friction = 0.5;
  die.x = Vec3(0, 0, 1);
  die.q = axisAngle(Vec3(1, 2, 0.5), 0.7);
  die.v = Vec3(1, 0, 0);
  die.omega = Vec3(3, -5, 2);
  w.bodies.push_back(die);
  EnergyLedger3d ledger(w);
  w.advanceTo(4.0, &ledger);
  // auto began with event and handed over when the die stayed on the floor
  CHECK(w.collisions() == CollisionMethod::Sequential);
  REQUIRE(w.methodSwitch());
  const Body& b = w.bodies[0];
  CHECK(b.v.norm() <= 1e-9);
  CHECK(b.omega.norm() <= 1e-9);
  // on a face: one of its axes along z, its center half a side up
  const Mat3 axes = b.rotation();
  CHECK(axes.row(2).cwiseAbs().maxCoeff() >= std::cos(sim::core::settings::kLinearSlop / 0.1));
  CHECK(std::abs(b.x.z() - 0.1) <= sim::core::settings::kLinearSlop);
  CHECK(ledger.largestRise().amount <= 1e-2);
}

TEST_CASE("a box at rest on the floor stays at rest under every integrator") {
  for (const Integrator integrator : kIntegrators)
    for (const double dt : {0.001, 1.0 / 60.0}) {
      CAPTURE(kIntegratorNames.name(integrator));
      CAPTURE(dt);
      World w = onFloor(0.5, integrator);
      w = fixtures::redefined(w, [&](auto& d) {
        d.dt = dt;
        d.collisions = CollisionMethod::Sequential;
      });
      Body box = makeBody(makeBox(Vec3(0.4, 0.3, 0.2)), 10.0);
      box.x = Vec3(0, 0, 0.1);
      w.bodies.push_back(box);
      w.advanceTo(2.0);
      CHECK(w.bodies[0].v.norm() + w.bodies[0].omega.norm() <= 1e-9);
      CHECK(std::abs(w.bodies[0].x.z() - 0.1) <= sim::core::settings::kLinearSlop);
    }
}

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/world3d/diagnostics.h"
#include "sim/world3d/integrators.h"
#include "support/world3d_fixtures.h"
#include "support/redefined.h"

using namespace sim::world3d;

using fixtures3d::runDrift;

TEST_CASE("a free asymmetric body: the splitting keeps L to round-off over 10⁴ steps and E within a bounded band") {
  const double h = 0.01, until = 100.0;  // ω ≈ 3.7 rad/s: h|ω| = 0.037, about 60 turns
  const fixtures3d::Drift split = runDrift(fixtures3d::freeBox(Integrator::Splitting, h), until);
  REQUIRE(split.energyError.size() == 10000);
  const double firstQuarter = split.largestEnergyError(0, 2500), lastQuarter = split.largestEnergyError(7500, 10000);
  MESSAGE("splitting, 10^4 steps of 0.01 s: |dL|/|L| <= ", split.momentum, ", |dE|/E <= ", firstQuarter,
          " in the first quarter, ", lastQuarter, " in the last");
  CHECK(split.momentum <= settings::kConservedRoundOff);
  // bounded: the energy error swings with the motion and does not grow (no secular drift)
  CHECK(lastQuarter <= 1.5 * firstQuarter);
  // and it is second order small: a few (h|ω|)²
  CHECK(firstQuarter < 5e-3);
}

TEST_CASE("the splitting keeps |q| = 1 to round-off without any normalization") {
  World w = fixtures3d::freeBox(Integrator::Splitting, 0.01);
  w = fixtures::redefined(w, [&](auto& d) { d.normalizeQuaternions = false; });
  w.advanceTo(100.0);
  MESSAGE("| |q| - 1 | after 10^4 unnormalized steps: ", quaternionDrift(w));
  // a product of unit quaternions rounds by a few ulps a step, adding up as a random walk
  CHECK(quaternionDrift(w) <= settings::kConservedRoundOff);
}

TEST_CASE("the splitting is symmetric: a step of −h undoes a step of h") {
  World w = fixtures3d::freeBox(Integrator::Splitting, 0.01);
  w = fixtures::redefined(w, [&](auto& d) {
    d.forces.gravity = Vec3(0, 0, -9.81);  // a kick as well as the free flow
  });
  States y(w.bodies.begin(), w.bodies.end());
  const States start = y;
  const Dynamics f{w.bodies, w.def().forces, 0.0};
  splittingStep(f, 0.05, y);
  CHECK((y[0].q.coeffs() - start[0].q.coeffs()).norm() > 0.01);
  splittingStep(f, -0.05, y);
  CHECK((y[0].x - start[0].x).norm() < 1e-15);
  CHECK((y[0].v - start[0].v).norm() < 1e-14);
  CHECK((y[0].q.coeffs() - start[0].q.coeffs()).norm() < 1e-15);
  CHECK((y[0].omega - start[0].omega).norm() < 1e-14);
}

TEST_CASE("two bodies joined by a spring: the splitting keeps p and L about the origin to round-off") {
  // internal forces only: each kick adds f and −f at points on one line, so Σ p and Σ (x × p + L)
  // are untouched; the drift moves x along v and the free flow keeps each body's L
  World w = fixtures3d::springChain(Integrator::Splitting, 0.01);
  w = fixtures::redefined(w, [&](auto& d) {
    d.forces.gravity.setZero();
    d.forces.springs.erase(d.forces.springs.begin());  // the world anchor would be an external force
    d.forces.drags.clear();
    d.forces.springs[0].damping = 0.0;
  });
  w.bodies[0].v = Vec3(0.3, 0, 0);
  const Vec3 p0 = linearMomentum(w), l0 = angularMomentum(w);
  const double e0 = energy(w).total();
  w.advanceTo(100.0);
  MESSAGE("|dp| = ", (linearMomentum(w) - p0).norm(), ", |dL|/|L| = ", (angularMomentum(w) - l0).norm() / l0.norm(),
          ", |dE|/E = ", std::abs(energy(w).total() - e0) / e0);
  CHECK((linearMomentum(w) - p0).norm() <= settings::kConservedRoundOff * p0.norm());
  CHECK((angularMomentum(w) - l0).norm() <= settings::kConservedRoundOff * l0.norm());
  CHECK(std::abs(energy(w).total() - e0) < 0.01 * e0);
}

TEST_CASE("the splitting's order is 2, on the free body and on the coupled scene with damping") {
  struct Case {
    std::string scene;
    World (*make)(Integrator, double);
    double largest;
  };
  auto freeBox = [](Integrator m, double dt) { return fixtures3d::freeBox(m, dt); };
  for (const Case& c : {Case{"free box", +freeBox, 0.02}, Case{"spring chain", &fixtures3d::springChain, 4e-3}}) {
    CAPTURE(c.scene);
    const double until = 1.0;
    World reference = c.make(Integrator::Rk4, 1.0 / 25600);
    reference.advanceTo(until);
    std::vector<double> dts, errors;
    for (double dt = c.largest; dts.size() < 4; dt /= 2) {
      World w = c.make(Integrator::Splitting, dt);
      w.advanceTo(until);
      dts.push_back(dt);
      errors.push_back(fixtures3d::stateDistance(w, reference));
    }
    const double order = fixtures3d::fittedOrder(dts, errors);
    MESSAGE(c.scene, ": errors ", errors[0], ", ", errors[1], ", ", errors[2], ", ", errors[3], " at dt ", dts.front(), " to ",
            dts.back(), ": fitted order ", order);
    CHECK(std::abs(order - 2.0) <= settings::kOrderTolerance);
  }
}

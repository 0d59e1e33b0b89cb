#include "sim/world3d/integrators.h"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

#include "support/world3d_fixtures.h"
#include "support/redefined.h"

using namespace sim::world3d;

namespace {

constexpr Integrator kClassic[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Midpoint, Integrator::Rk4};

// a box spun about its z axis, which is the world's: q = [w 0 0 z] for all time, so R(q) keeps z
// fixed even as |q| drifts, ω stays constant (ω × I ω = 0) and q̇ = ½ (0, ω) q is linear with
// constant coefficients
World principalSpin(Integrator method, double dt, bool normalize) {
  World w = fixtures3d::freeBox(method, dt, Vec3(0, 0, 4.0));
  w.bodies[0].q = Quat::Identity();
  w = fixtures::redefined(w, [&](auto& d) { d.normalizeQuaternions = normalize; });
  return w;
}

// the modulus of an explicit Runge–Kutta method's stability function R(z) at z = i y: a step
// multiplies q by R(h Ω/2), Ω = (0, ω) left-multiplied, whose eigenvalues are ±i|ω|, so
// |q| grows by |R(i h |ω| / 2)| a step
double stepGrowth(Integrator method, double y) {
  const std::complex<double> z(0.0, y);
  switch (method) {
    case Integrator::ExplicitEuler:
    case Integrator::SymplecticEuler: return std::abs(1.0 + z);  // ω is constant: both are Euler on q
    case Integrator::Midpoint: return std::abs(1.0 + z + z * z / 2.0);
    case Integrator::Rk4: return std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
    case Integrator::Splitting: return 1.0;
  }
  return 0.0;
}

}  // namespace

TEST_CASE("names: the 2D world's four and splitting, each with its order") {
  CHECK(kIntegratorNames.list() == "explicit_euler, symplectic_euler, midpoint, rk4, splitting");
  CHECK(kIntegratorNames.parse("splitting") == Integrator::Splitting);
  CHECK(!kIntegratorNames.parse("leapfrog"));
  CHECK(integratorOrder(Integrator::ExplicitEuler) == 1);
  CHECK(integratorOrder(Integrator::Rk4) == 4);
  CHECK(integratorOrder(Integrator::Splitting) == 2);
}

TEST_CASE("normalized: |q| = 1 to round-off after 10⁶ steps of explicit Euler on a wandering ω") {
  World w = fixtures3d::freeBox(Integrator::ExplicitEuler, 1e-3);
  struct Worst : StepObserver {
    double drift = 0.0;
    void afterStep(const World& world) override { drift = std::max(drift, quaternionDrift(world)); }
  } worst;
  w.advanceTo(1000.0, &worst);
  CHECK(w.steps == 1000000);
  MESSAGE("largest | |q| - 1 | over 10^6 normalized steps: ", worst.drift);
  CHECK(worst.drift <= settings::kUnitNormRoundOff);
  // without the normalization the same run ends far off: one step alone puts |q| off by (h|ω|)²/8
  World loose = fixtures3d::freeBox(Integrator::ExplicitEuler, 1e-3);
  loose = fixtures::redefined(loose, [&](auto& d) { d.normalizeQuaternions = false; });
  loose.advanceTo(1.0);
  CHECK(quaternionDrift(loose) > 1e3 * settings::kUnitNormRoundOff);
}

TEST_CASE("the free box over 10⁴ steps of 0.01 s: no four-vector method keeps L or E") {
  struct Expect {
    Integrator method;
    double energyAtEnd;  // the sign and size of (E − E₀)/E₀ after 100 s, roughly
  };
  for (const Expect& e : {Expect{Integrator::ExplicitEuler, -0.2}, Expect{Integrator::SymplecticEuler, 40.0},
                          Expect{Integrator::Midpoint, -2.6e-4}, Expect{Integrator::Rk4, -2.6e-7}}) {
    CAPTURE(kIntegratorNames.name(e.method));
    const fixtures3d::Drift d = fixtures3d::runDrift(fixtures3d::freeBox(e.method, 0.01), 100.0);
    MESSAGE(kIntegratorNames.name(e.method), ": |dL|/|L| <= ", d.momentum, ", (E - E0)/E0 at the end ", d.energyError.back());
    CHECK(d.momentum > 1e3 * settings::kConservedRoundOff);
    // explicit Euler loses energy here (with q normalized), symplectic Euler gains it fast: in 3D
    // its four-vector q update makes it no symplectic method
    const double ratio = d.energyError.back() / e.energyAtEnd;
    CHECK(ratio > 0.5);
    CHECK(ratio < 2.0);
  }
}

TEST_CASE("unnormalized: |q| drifts by the stability function's modulus, (1 + (h|ω|/2)²)^(n/2) for explicit Euler") {
  const double h = 0.01, omega = 4.0;
  const int n = 1000;
  for (Integrator m : kClassic) {
    CAPTURE(kIntegratorNames.name(m));
    World w = principalSpin(m, h, false);
    w.advanceTo(n * h);
    const double expected = std::pow(stepGrowth(m, h * omega / 2), n);
    MESSAGE(kIntegratorNames.name(m), ": |q| after ", n, " steps of h|w| = ", h * omega, ": |q| - 1 = ", w.bodies[0].q.norm() - 1,
            " (closed form ", expected - 1, ")");
    // relative round-off of n steps, each a few ulps
    CHECK(fixtures3d::relativeError(w.bodies[0].q.norm(), expected) < 1e-12);
    // ω stays exactly where it was: the principal spin is a fixed point of Euler's equations
    CHECK((w.bodies[0].omega - principalSpin(m, h, false).bodies[0].omega).norm() < 1e-12);
  }
  // a q off unit length gives an R(q) that is no rotation and inertias I, I⁻¹ that disagree: on the
  // wandering free box, explicit and symplectic Euler without normalization diverge within 10 s
  for (Integrator m : {Integrator::ExplicitEuler, Integrator::SymplecticEuler}) {
    World w = fixtures3d::freeBox(m, 0.01);
    w = fixtures::redefined(w, [&](auto& d) { d.normalizeQuaternions = false; });
    CHECK_THROWS_AS(w.advanceTo(10.0), sim::core::Diverged);
  }
  // explicit Euler's drift, spelled out: (1 + 0.0004)^500
  CHECK(fixtures3d::relativeError(std::pow(stepGrowth(Integrator::ExplicitEuler, 0.02), n), std::pow(1.0004, 500)) < 1e-12);
}

TEST_CASE("orders 1, 1, 2, 4 of the four classic integrators on a coupled 3D scene") {
  const double until = 1.0;
  World reference = fixtures3d::springChain(Integrator::Rk4, 1.0 / 25600);
  reference.advanceTo(until);
  struct Case {
    Integrator method;
    double largest;  // the largest dt of four halvings, in the method's asymptotic range
  };
  for (const Case& c : {Case{Integrator::ExplicitEuler, 1e-3}, Case{Integrator::SymplecticEuler, 1e-3},
                        Case{Integrator::Midpoint, 4e-3}, Case{Integrator::Rk4, 2e-2}}) {
    CAPTURE(kIntegratorNames.name(c.method));
    std::vector<double> dts, errors;
    for (double dt = c.largest; dts.size() < 4; dt /= 2) {
      World w = fixtures3d::springChain(c.method, dt);
      w.advanceTo(until);
      dts.push_back(dt);
      errors.push_back(fixtures3d::stateDistance(w, reference));
    }
    const double order = fixtures3d::fittedOrder(dts, errors);
    MESSAGE(kIntegratorNames.name(c.method), ": errors ", errors[0], ", ", errors[1], ", ", errors[2], ", ", errors[3], " at dt ",
            dts.front(), " to ", dts.back(), ": fitted order ", order);
    CHECK(std::abs(order - integratorOrder(c.method)) <= settings::kOrderTolerance);
  }
}

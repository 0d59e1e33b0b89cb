#include "sim/world3d/closed_forms.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "sim/world3d/diagnostics.h"
#include "sim/world3d/measures.h"
#include "support/world3d_fixtures.h"
#include "support/redefined.h"

using namespace sim::world3d;
using fixtures3d::relativeError;

namespace {

// a world of free bodies stepped by `method` at `dt`
WorldDef stepping(Integrator method, double dt) {
  WorldDef def;
  def.integrator = method;
  def.dt = dt;
  return def;
}

// a torque-free symmetric ellipsoid, semi-axes (0.3, 0.3, 0.1): I₁ = I₂ = 0.02 m, I₃ = 0.036 m
World symmetricTop(Integrator method, double dt, const Vec3& omegaBody) {
  Body top = makeBody(makeEllipsoid(Vec3(0.3, 0.3, 0.1)), 100.0);
  top.q = axisAngle(Vec3(1, -2, 0.5), 0.7);
  top.omega = top.rotation() * omegaBody;
  return World(stepping(method, dt), {top});
}

// a box of sides 0.1 × 0.4 × 0.8 spun at 4 rad/s about y, its middle axis, nudged by 0.1 rad/s
// about the others: ω₂ flips sign twice a period
World racket(Integrator method, double dt) {
  Body box = makeBody(makeBox(Vec3(0.1, 0.4, 0.8)), 1.0 / 0.032);
  box.omega = Vec3(0.1, 4.0, 0.1);
  return World(stepping(method, dt), {box});
}

// the period of ω_b,y measured over `periods` periods: from its sign changes, each located on
// Hermite's cubic between the steps around it (two changes a period)
double measuredFlipPeriod(World w, int periods) {
  struct Crossings : StepObserver {
    explicit Crossings(const World& w) : measures(w.bodies[0], w.time) {}
    void afterStep(const World& world) override { measures.add(world.bodies[0], world.time); }
    FreeBodyMeasures measures;
  } crossings(w);
  const size_t needed = 2 * periods + 1;
  while (crossings.measures.signChanges() < needed && w.time < 100.0) w.advanceTo(w.time + 1.0, &crossings);
  REQUIRE(crossings.measures.signChanges() >= needed);  // a body that never flips fails here, not by hanging
  return crossings.measures.flipPeriod();
}

}  // namespace

TEST_CASE("K(k) by the arithmetic–geometric mean against std::comp_ellint_1 and K(1/√2) = Γ(1/4)²/(4√π)") {
  CHECK(completeEllipticK(0.0) == std::numbers::pi / 2);
  CHECK(relativeError(completeEllipticK(std::sqrt(0.5)), std::pow(std::tgamma(0.25), 2) / (4 * std::sqrt(std::numbers::pi))) <
        1e-15);
  for (double k : {0.1, 0.5, 0.9, 0.99, 0.999999}) {
    CAPTURE(k);
    // libstdc++ forms 1 − k², which at k = 0.999999 costs it 1e-12 (K ≈ ln(4/k′), and k′ is then
    // known to 5e-11); the AGM takes k′ from (1 − k)(1 + k)
    CHECK(relativeError(completeEllipticK(k), std::comp_ellint_1(k)) < (k < 0.999 ? 1e-14 : 1e-11));
  }
  // from the complementary modulus near k = 1: K ≈ ln(4/k′)
  CHECK(relativeError(completeEllipticKOfComplement(1e-12), std::log(4e12)) < 1e-12);
  CHECK(std::isinf(completeEllipticK(1.0)));
  CHECK_THROWS_AS(completeEllipticK(1.5), std::invalid_argument);
}

TEST_CASE("the symmetric top: Ω = ω₃ (I₃ − I₁)/I₁ in the body, |L|/I₁ in space, a constant cone angle") {
  for (const Vec3& omegaBody : {Vec3(1.0, 0.0, 5.0), Vec3(-2.0, 1.0, -3.0)}) {
    const World start = symmetricTop(Integrator::Splitting, 1e-3, omegaBody);
    const Body& b0 = start.bodies[0];
    const SymmetricTop top{b0.principalMoments[0], b0.principalMoments[2], omegaBody};
    REQUIRE(relativeError(b0.principalMoments[1], top.transverse) < 1e-14);
    // measured from the run: ω in the body turns about z, ω in space turns about L
    struct Precession : StepObserver {
      TurningAngle body, space;
      double coneError = 0.0, coneAngle = 0.0;
      void afterStep(const World& w) override {
        const Body& b = w.bodies[0];
        body.add(b.rotation().transpose() * b.omega);
        space.add(b.omega);
        const Vec3 l = b.angularMomentum();
        coneError = std::max(coneError, std::abs(std::atan2(b.omega.cross(l).norm(), b.omega.dot(l)) - coneAngle));
      }
    } p;
    p.body = TurningAngle(Vec3::UnitZ());
    p.space = TurningAngle(b0.angularMomentum());
    p.coneAngle = coneAngle(top);
    World w = start;
    p.afterStep(w);  // the first sample, at t = 0
    w.advanceTo(10.0, &p);
    const double bodyRate = p.body.turned() / w.time, spaceRate = p.space.turned() / w.time;
    MESSAGE("omega_b = ", omegaBody.transpose(), ": body precession ", bodyRate, " rad/s (relative error ",
            relativeError(bodyRate, bodyPrecessionRate(top)), "), space precession ", spaceRate, " rad/s (",
            relativeError(spaceRate, spacePrecessionRate(top)), "), cone angle within ", p.coneError, " rad");
    // the splitting's O(h²) error: (h|ω|)², 2.6e-5 and 1.4e-5 here
    const double splittingError = std::pow(w.def().dt * omegaBody.norm(), 2);
    CHECK(relativeError(bodyRate, bodyPrecessionRate(top)) < splittingError);
    CHECK(relativeError(spaceRate, spacePrecessionRate(top)) < splittingError);
    CHECK(p.coneError < 1e-6);
    // the symmetry axis keeps its angle to L
    const Vec3 axis = w.bodies[0].rotation().col(2), l = w.bodies[0].angularMomentum();
    CHECK(std::abs(std::acos(axis.dot(l) / l.norm()) - symmetryAxisAngle(top)) < 1e-6);
  }
}

TEST_CASE("the flip period from K(k) (Landau & Lifshitz §37) against the simulated box spun near its middle axis") {
  const World start = racket(Integrator::Rk4, 1e-3);
  const Body& b = start.bodies[0];
  const Vec3 moments = b.inertiaBody.diagonal();  // the box's axes are principal
  const double expected = flipPeriod(moments, b.omega);
  CHECK(relativeError(flipPeriod(moments, kineticEnergy(b).rotational, b.angularMomentum().norm()), expected) < 1e-9);
  const double rk4 = measuredFlipPeriod(start, 3);
  const double split = measuredFlipPeriod(racket(Integrator::Splitting, 1e-3), 3);
  const double splitCoarse = measuredFlipPeriod(racket(Integrator::Splitting, 1e-2), 3);
  const double euler = measuredFlipPeriod(racket(Integrator::ExplicitEuler, 1e-3), 3);
  MESSAGE("flip period ", expected, " s (a flip every ", expected / 2,
          " s); relative errors measured over 3 periods: rk4 (dt 1e-3) ", relativeError(rk4, expected), ", splitting (dt 1e-3) ",
          relativeError(split, expected), ", splitting (dt 1e-2) ", relativeError(splitCoarse, expected),
          ", explicit Euler (dt 1e-3) ", relativeError(euler, expected));
  // RK4 to the interpolation of the crossings; the splitting to its O(h²) error, 100 times larger at
  // 10 times the step; explicit Euler, whose E and L drift, is off by half
  CHECK(relativeError(rk4, expected) < 1e-7);
  CHECK(relativeError(split, expected) < 1e-5);
  CHECK(relativeError(splitCoarse, expected) < 1e-3);
  CHECK(relativeError(euler, expected) > 0.1);
}

TEST_CASE("the flip period's limits: small wobbles about the largest axis, and the separatrix") {
  const Vec3 moments(1.0, 2.0, 3.0);
  // about I₃ with a small wobble: 2π/ω₃ · √(I₁ I₂ / ((I₃ − I₁)(I₃ − I₂)))
  const double omega3 = 2.0;
  const double wobble = 2 * std::numbers::pi / omega3 * std::sqrt(1.0 * 2.0 / (2.0 * 1.0));
  CHECK(relativeError(flipPeriod(moments, Vec3(1e-6, 1e-6, omega3)), wobble) < 1e-9);
  // any order of the moments
  CHECK(flipPeriod(Vec3(3, 1, 2), Vec3(omega3, 1e-6, 1e-6)) == flipPeriod(moments, Vec3(1e-6, 1e-6, omega3)));
  // exactly about the middle axis: on the separatrix, it never comes back
  CHECK(std::isinf(flipPeriod(moments, Vec3(0, 1, 0))));
  CHECK_THROWS_AS(flipPeriod(Vec3(1, 1, 2), Vec3(1, 1, 1)), std::invalid_argument);
}

TEST_CASE("the notes' poll in 3D: the bar (l = 4, m = 3, I = 4) struck by j = (1, 0, 0) at its center or its end") {
  const Mat3 inertia = Vec3(4.0, 4.0, 0.1).asDiagonal();  // the bar along z
  const ImpulseOutcome center =
      afterImpulse(3.0, inertia, Quat::Identity(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3(1, 0, 0));
  CHECK(center.velocity.isApprox(Vec3(1.0 / 3, 0, 0)));
  CHECK(center.angularVelocity.isZero());
  CHECK(relativeError(center.kineticEnergyAfter, 1.0 / 6) < 1e-15);
  const ImpulseOutcome end =
      afterImpulse(3.0, inertia, Quat::Identity(), Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, 2), Vec3(1, 0, 0));
  CHECK(end.velocity.isApprox(Vec3(1.0 / 3, 0, 0)));
  CHECK(end.angularVelocity.isApprox(Vec3(0, 0.5, 0)));  // r′ × j = (0, 2, 0), I⁻¹ of it
  CHECK(relativeError(end.kineticEnergyAfter, 2.0 / 3) < 1e-15);
  CHECK(end.kineticEnergyBefore == 0.0);

  // the world's timed impulse on a turned, moving bar gives the closed form's answer
  World w;
  Body bar = makeBody(makeBox(Vec3(0.2, 0.2, 4.0)), 3.0, inertia);
  bar.q = axisAngle(Vec3(1, 1, 0), 0.6);
  bar.v = Vec3(0.2, 0, 0);
  bar.omega = Vec3(0, 0, 0.3);
  const ImpulseOutcome expected =
      afterImpulse(3.0, inertia, bar.q, bar.v, bar.omega, bar.rotation() * Vec3(0, 0, 2), Vec3(1, 0, 0));
  w.bodies.push_back(bar);
  w = fixtures::redefined(w, [&](auto& d) { d.events.push_back({0.0, 0, Vec3(0, 0, 2), false, Vec3(1, 0, 0)}); });
  w.advanceTo(0.0);
  CHECK(w.bodies[0].v.isApprox(expected.velocity, 1e-15));
  CHECK(w.bodies[0].omega.isApprox(expected.angularVelocity, 1e-14));
  CHECK(relativeError(kineticEnergy(w.bodies[0]).total(), expected.kineticEnergyAfter) < 1e-14);
}

// The measures the closed forms are compared against: a turning angle unwrapped over many turns,
// sign changes located on Hermite's cubic, and a body's principal axes with a definite sign.
#include "sim/world3d/measures.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sim::world3d;

TEST_CASE("a turning angle counts whole turns, right-handed about its axis") {
  TurningAngle a(Vec3(0, 0, 2));
  TurningAngle backwards(Vec3(0, 0, -1));
  for (int k = 0; k <= 300; ++k) {
    const double angle = 0.1 * k;  // 30 rad: nearly five turns
    const Vec3 v(std::cos(angle), std::sin(angle), 0.3);
    a.add(v);
    backwards.add(v);
  }
  CHECK(a.turned() == doctest::Approx(30.0).epsilon(1e-14));
  CHECK(backwards.turned() == doctest::Approx(-30.0).epsilon(1e-14));
}

TEST_CASE("sign changes of sin t sampled 0.1 apart: at kπ to O(h⁴), and the period 2π") {
  SignChanges changes;
  double straightLineError = 0.0, last = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.1 * k - 0.05;
    const double f = std::sin(t);
    if (k > 1 && (f < 0) != (last < 0)) {
      // what a straight line between the samples would give
      const double t0 = t - 0.1;
      const double root = t0 + 0.1 * last / (last - f);
      straightLineError = std::max(straightLineError, std::abs(root - std::numbers::pi * std::round(root / std::numbers::pi)));
    }
    last = f;
    changes.add(t, f, std::cos(t));
  }
  REQUIRE(changes.times().size() == 3);  // π, 2π, 3π within 10
  double hermiteError = 0.0;
  for (size_t i = 0; i < 3; ++i) hermiteError = std::max(hermiteError, std::abs(changes.times()[i] - (i + 1) * std::numbers::pi));
  MESSAGE("crossings off by ", hermiteError, " (a straight line: ", straightLineError, ")");
  CHECK(hermiteError < 1e-6);
  CHECK(straightLineError > 100 * hermiteError);
  CHECK(changes.period() == doctest::Approx(2 * std::numbers::pi).epsilon(1e-6));
  CHECK(std::isnan(SignChanges().period()));
}

TEST_CASE("a box's principal axes are its own axes with a positive sign; a top's symmetry axis") {
  // the smallest moment is about the longest side
  const Body box = makeBody(makeBox(Vec3(0.1, 0.4, 0.8)), 1.0);
  CHECK(principalAxis(box, 0) == Vec3::UnitZ());
  CHECK(principalAxis(box, 1) == Vec3::UnitY());
  CHECK(principalAxis(box, 2) == Vec3::UnitX());
  CHECK(symmetryAxisIndex(Vec3(1, 1, 2)) == 2);
  CHECK(symmetryAxisIndex(Vec3(1, 2, 2)) == 0);
}

// cos and sin of a substep's turn (step_turn.h): within round-off of the exact values (long double
// as the reference), the library's own values past the polynomials' bound, and libm's bits for the
// small turns of a resting pile.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "sim/world/step_turn.h"

namespace {

// |value − exact| in units in the last place of T in the exact value's binade
template <class T>
double ulps(T value, long double exact) {
  int e = 0;
  std::frexp(static_cast<double>(exact), &e);
  const long double ulp = std::ldexp(1.0L, e - std::numeric_limits<T>::digits);
  return static_cast<double>(std::abs(static_cast<long double>(value) - exact) / ulp);
}

// the worst error in ulps of stepTurn over `n` turns drawn evenly from [−bound, bound]
template <class T>
double worstUlps(double bound, int n) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> turn(-bound, bound);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = turn(random);
    T c, s;
    sim::world::stepTurn(x, c, s);
    worst = std::max({worst, ulps<T>(c, cosl(x)), ulps<T>(s, sinl(x))});
  }
  return worst;
}

}  // namespace

TEST_CASE("a substep's turn in doubles: within 0.55 ulp of the exact cos and sin up to the polynomials' bound") {
  CHECK(worstUlps<double>(0.25, 200000) < 0.55);
  CHECK(worstUlps<double>(1e-3, 200000) < 0.55);
}

TEST_CASE("a substep's turn in doubles: libm's bits for a resting pile's turns, and past the bound") {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> small(-1e-4, 1e-4);
  int differ = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = small(random);
    double c, s;
    sim::world::stepTurn(x, c, s);
    differ += c != std::cos(x) || s != std::sin(x);
  }
  CHECK(differ == 0);
  for (const double x : {std::nextafter(0.25, 1.0), 0.3, 1.0, -2.5, 3.0}) {
    double c, s;
    sim::world::stepTurn(x, c, s);
    CHECK(c == std::cos(x));
    CHECK(s == std::sin(x));
  }
  // no turn is no turn
  double c0, s0;
  sim::world::stepTurn(0.0, c0, s0);
  CHECK(c0 == 1.0);
  CHECK(s0 == 0.0);
}

TEST_CASE("a substep's turn in floats: within a float's rounding of the exact cos and sin, and the library past 1/2") {
  CHECK(worstUlps<float>(0.5, 200000) < 0.51);
  float c, s;
  sim::world::stepTurn(1.5, c, s);
  CHECK(c == static_cast<float>(std::cos(1.5)));
  CHECK(s == static_cast<float>(std::sin(1.5)));
}

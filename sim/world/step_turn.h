// cos and sin of how far a body turned since the step began, as soft_step's substeps need them for
// each body (the separations move with the exact rotation: see integratePositions). A step turns a
// body by little, so Taylor's polynomials serve below a bound and the library past it: the libm
// call was 6 % of a step on the 5,050-box pyramid in floats and 8 % in doubles.
#pragma once

#include <cmath>

namespace sim::world {

// to a float: polynomials to x⁸ and x⁹ for |x| ≤ 1/2, then rounded once (the terms left out are
// under 0.005 of a float's last place there: within 0.51 ulp of the exact values; the sine stopped
// at x⁷, as it once did, was 0.68 ulp off at |x| = 1/2)
inline void stepTurn(double x, float& c, float& s) {
  if (!(std::abs(x) <= 0.5)) {
    c = static_cast<float>(std::cos(x)), s = static_cast<float>(std::sin(x));
    return;
  }
  const double x2 = x * x;
  c = static_cast<float>(1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320)))));
  s = static_cast<float>(x * (1.0 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880))))));
}

// to a double: polynomials to x¹² and x¹³ for |x| ≤ 1/4 (the terms left out are below 10⁻¹⁹
// there), within 0.55 ulp of the exact values as libm's are within 0.52, and the same bits as
// libm's for the turns of a resting pile's substeps, under 10⁻⁴ rad (tests/sim/world/step_turn_test.cpp)
inline void stepTurn(double x, double& c, double& s) {
  if (!(std::abs(x) <= 0.25)) {
    c = std::cos(x), s = std::sin(x);
    return;
  }
  const double x2 = x * x;
  c = 1.0 +
      x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 + x2 * (1.0 / 479001600))))));
  // x plus the rest, so that the leading term is exact and the rounding falls on the small part
  s = x +
      x * (x2 * (-1.0 / 6 +
                 x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800 + x2 * (1.0 / 6227020800)))))));
}

}  // namespace sim::world

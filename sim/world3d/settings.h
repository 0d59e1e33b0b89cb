// Every tunable number of the 3D layer, and the tolerances its checks hold the physics to, with
// unit and why. The time step, the duration and the snapping of instants to the step grid are the
// 2D world's (sim/core/settings.h).
#pragma once

#include <limits>

namespace sim::world3d::settings {

// default density, kg/m³ (volume density in 3D), when neither density nor mass is given: a unit
// cube weighs 1 kg, so that a scene's numbers stay simple, as the 2D default of 1 kg/m²
inline constexpr double kDefaultDensity = 1.0;

// a quaternion typed in a scene is accepted, and normalized, when its length is within this of 1
// (relative): [0.7071068, 0.7071068, 0, 0], typed to 7 digits, is 4e-8 off; a quaternion further
// off than 1e-6 is a mistake, not round-off
inline constexpr double kUnitQuaternionTolerance = 1e-6;

// an inertia tensor's off-diagonal pair I_ij, I_ji may differ by this fraction of its largest
// entry: typed tensors are symmetric exactly, computed ones to round-off
inline constexpr double kInertiaSymmetryTolerance = 1e-9;

// principal moments must satisfy the triangle inequality I₁ + I₂ ≥ I₃ (every mass distribution
// does; a flat plate meets it with equality), allowed to fail by this fraction of I₃ for round-off
inline constexpr double kInertiaTriangleTolerance = 1e-9;

// the arithmetic–geometric mean of the elliptic integral stops when a and g agree to this
// (relative): it converges quadratically, so a handful of iterations reach it
inline constexpr double kEllipticTolerance = 4 * std::numeric_limits<double>::epsilon();

// --- tolerances of the checks (tests now, `expect` later) ---

// ||q| − 1| after normalizing, dimensionless: q/|q| rounds the norm and four quotients, a few ulps
inline constexpr double kUnitNormRoundOff = 4 * std::numeric_limits<double>::epsilon();

// relative change of a quantity that the method conserves exactly in exact arithmetic (angular
// momentum under the splitting, linear momentum under internal forces), over 10⁴ steps: each step
// rounds it by a few ulps and the errors add up as a random walk, about 1e-14; ×100 for margin
inline constexpr double kConservedRoundOff = 1e-12;

// a measured convergence order (slope of log error against log dt) may differ from the method's
// order by this: the error constant changes slowly with dt before the asymptotic range is reached
inline constexpr double kOrderTolerance = 0.25;

}  // namespace sim::world3d::settings

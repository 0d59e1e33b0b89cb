// Shared 3D scenes and measures for tests/sim/world3d: the 3D layer has no scene files yet, so its
// scenes are built here in code, once.
#pragma once

#include <cmath>

namespace fixtures3d {

// |actual − expected| / |expected| (doctest's Approx adds 1 to the scale, which makes it an
// absolute test for small quantities)
inline double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

}  // namespace fixtures3d

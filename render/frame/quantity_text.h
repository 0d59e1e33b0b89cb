// Values as the lecture overlays write them: three significant digits in plain notation (from 0.001
// to 10,000), a true minus sign (U+2212), the unit after a space, e.g. "ω = −0.500 rad/s"
// (sim::describe::numberText, the one format of every value a frame shows).
#pragma once

#include <cmath>
#include <string>

#include "sim/core/math.h"

namespace render::frame {

// a value below this fraction of its quantity's largest in the run is round-off, and is shown as 0
// (a ball's ½Iω² of 7.19 × 10⁻³⁸ J beside 4 J; a double carries 16 digits, a run loses a few)
inline constexpr double kNoiseFloor = 1e-12;
// the noise floor of a quantity whose largest magnitude in the run is `scale`
inline double noiseFloor(double scale) { return kNoiseFloor * std::abs(scale); }

// a time as a title, a label or the page writes it: to the millisecond, as the frame's clock, without
// trailing zeros ("0", "2.5", "0.765")
std::string timeToMs(double t);
// x to `decimals` decimals, negative with "−"; −0.00 written 0.00
std::string signedNumber(double x, int decimals = 2);
// x to three significant digits (sim::describe::numberText), 0 below `zeroBelow`
std::string numberText(double x, double zeroBelow = 0.0);
// "name = x unit"; each number 0 below `zeroBelow` (its quantity's noise floor)
std::string quantityText(const std::string& name, double x, const std::string& unit, double zeroBelow = 0.0);
// "name = (x, y) unit"
std::string vectorText(const std::string& name, const sim::core::Vec2& v, const std::string& unit, double zeroBelow = 0.0);
// "name = (x, y, z) unit"
std::string vectorText(const std::string& name, const Eigen::Vector3d& v, const std::string& unit, double zeroBelow = 0.0);

}  // namespace render::frame

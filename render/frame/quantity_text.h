// Values as the lecture overlays write them: three significant digits in plain notation (from 0.001
// to 10,000), a true minus sign (U+2212), the unit after a space, e.g. "ω = −0.500 rad/s"
// (sim::debug::numberText, the one format of every value a frame shows).
#pragma once

#include <string>

#include "sim/core/math.h"

namespace render::frame {

// x to `decimals` decimals, negative with "−"; −0.00 written 0.00
std::string signedNumber(double x, int decimals = 2);
// x to three significant digits (sim::debug::numberText)
std::string numberText(double x);
// "name = x unit"
std::string quantityText(const std::string& name, double x, const std::string& unit);
// "name = (x, y) unit"
std::string vectorText(const std::string& name, const sim::core::Vec2& v, const std::string& unit);
// "name = (x, y, z) unit"
std::string vectorText(const std::string& name, const Eigen::Vector3d& v, const std::string& unit);

}  // namespace render::frame

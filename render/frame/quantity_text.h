// Values as the lecture overlays write them: two decimals, a true minus sign (U+2212), the unit
// after a space, e.g. "ω = −0.50 rad/s".
#pragma once

#include <string>

#include "sim/core/math.h"

namespace render::frame {

// x to `decimals` decimals, negative with "−"; −0.00 written 0.00
std::string signedNumber(double x, int decimals = 2);
// "name = x unit"
std::string quantityText(const std::string& name, double x, const std::string& unit);
// "name = (x, y) unit"
std::string vectorText(const std::string& name, const sim::core::Vec2& v, const std::string& unit);
// "name = (x, y, z) unit"
std::string vectorText(const std::string& name, const Eigen::Vector3d& v, const std::string& unit);

}  // namespace render::frame

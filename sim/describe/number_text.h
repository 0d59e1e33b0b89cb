// Numbers as a slide writes them, the one format of every value shown (the simulator's
// separations, the renderer's overlays): three significant digits in plain notation from
// 0.001 to 10,000 ("0.00584", "−2.00", "1230"), a power of ten outside it ("5.84 × 10⁻¹³"), a true
// minus sign (U+2212), and 0 written "0".
#pragma once

#include <string>

namespace sim::describe {

// x to `digits` significant digits (1 to 17); |x| below `zeroBelow` is written "0"; a value that
// rounds to zero has no sign; NaN is "nan", ±∞ "∞" and "−∞"
std::string numberText(double x, int digits = 3, double zeroBelow = 0.0);

}  // namespace sim::describe

#include "render/frame/conserved_total.h"

#include <algorithm>
#include <cmath>

namespace render::frame {

namespace {

// a change below this fraction of the run's scale is round-off: a double carries 16 digits, and a
// run of 10⁶ steps loses at most about six of them
constexpr double kRoundOff = 1e-9;

}  // namespace

ConservedTotal::ConservedTotal(double initial, double scale)
    : initial_(initial), tolerance_(kRoundOff * std::max(std::abs(initial), std::abs(scale))) {}

double ConservedTotal::shown(double now) const { return std::abs(now - initial_) <= tolerance_ ? initial_ : now; }

}  // namespace render::frame

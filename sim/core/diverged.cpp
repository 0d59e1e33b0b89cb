#include "sim/core/diverged.h"

#include <string>

namespace sim::core {

Diverged::Diverged(double t, int b)
    : std::runtime_error("body " + std::to_string(b) + "'s state is no longer finite at t = " + std::to_string(t)),
      time(t),
      body(b) {}

}  // namespace sim::core

#include "sim/core/step_limit.h"

#include <cmath>
#include <sstream>

namespace sim::core {

double stepCount(double dt, double until) { return std::ceil(until / dt); }

std::string stepsOverLimit(double dt, double maxSteps, double until) {
  const double steps = stepCount(dt, until);
  if (steps <= maxSteps) return "";
  std::ostringstream m;
  m << "the run needs " << steps << " steps (" << until << " s at dt = " << dt << " s), more than the limit of "
    << maxSteps;
  return m.str();
}

}  // namespace sim::core

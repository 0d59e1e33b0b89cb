#include "sim/core/step_limit.h"

#include <cmath>
#include <sstream>

namespace sim::core {

double stepCount(double dt, double until) { return std::ceil(until / dt); }

std::string stepsOverLimit(double dt, double maxSteps, double until) {
  const double steps = stepCount(dt, until);
  if (steps <= maxSteps) return "";
  std::ostringstream m;
  m << "the run needs " << steps << " steps (" << until << " s at dt = " << dt << " s), more than the limit of " << maxSteps;
  return m.str();
}

std::string dtOverDuration(double dt, double duration) {
  if (!(duration > 0.0) || dt <= duration) return "";
  std::ostringstream m;
  m.precision(17);
  m << "dt = " << dt << " s is longer than the scene's duration of " << duration << " s: the run would take no step";
  return m.str();
}

}  // namespace sim::core

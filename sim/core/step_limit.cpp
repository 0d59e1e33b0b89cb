#include "sim/core/step_limit.h"

#include <cmath>
#include <sstream>

namespace sim::core {

double stepCount(double dt, double until) { return std::ceil(until / dt); }

std::pair<std::string, std::string> distinctCounts(double count, double limit) {
  std::string a, b;
  for (int digits = 6; digits <= 17 && a == b; ++digits) {
    std::ostringstream x, y;
    x.precision(digits), y.precision(digits);
    x << count, y << limit;
    a = x.str(), b = y.str();
  }
  return {a, b};
}

std::string stepsOverLimit(double dt, double maxSteps, double until) {
  const double steps = stepCount(dt, until);
  if (steps <= maxSteps) return "";
  const auto [count, limit] = distinctCounts(steps, maxSteps);
  std::ostringstream m;
  m << "the run needs " << count << " steps (" << until << " s at dt = " << dt << " s), more than the limit of " << limit;
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

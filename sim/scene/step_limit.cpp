#include "sim/scene/step_limit.h"

#include <cmath>
#include <sstream>

namespace sim::scene {

double stepCount(const SceneDef& def, double until) { return std::ceil(until / def.dt); }

std::string stepsOverLimit(const SceneDef& def, double until) {
  const double steps = stepCount(def, until);
  if (steps <= def.maxSteps) return "";
  std::ostringstream m;
  m << "the run needs " << steps << " steps (" << until << " s at dt = " << def.dt << " s), more than the limit of "
    << def.maxSteps;
  return m.str();
}

}  // namespace sim::scene

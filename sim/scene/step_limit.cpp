#include "sim/scene/step_limit.h"

#include "sim/core/step_limit.h"

namespace sim::scene {
using namespace sim::core;

double stepCount(const SceneDef& def, double until) { return sim::core::stepCount(def.dt, until); }

std::string stepsOverLimit(const SceneDef& def, double until) { return sim::core::stepsOverLimit(def.dt, def.maxSteps, until); }

}  // namespace sim::scene

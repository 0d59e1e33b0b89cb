// The bound on work (sim/core/step_limit.h) at a 2D scene's dt and max_steps.
#pragma once

#include <string>

#include "sim/scene/scene_def.h"

namespace sim::scene {

// the steps of a run from 0 to `until` at def.dt (rounded up)
double stepCount(const SceneDef& def, double until);

// "the run needs 1e+18 steps (1e+06 s at dt = 1e-12 s), more than the limit of 1e+08" when a
// run to `until` exceeds def.maxSteps, "" when it does not
std::string stepsOverLimit(const SceneDef& def, double until);

}  // namespace sim::scene

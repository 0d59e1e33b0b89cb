// A bound on work: a run of `until` seconds at the scene's dt takes until / dt steps, and a typo
// in dt (1e-12 for 1e-2) would otherwise run for years with no output.
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

// A bound on work: a run of `until` seconds at a step dt takes until / dt steps, and a typo in dt
// (1e-12 for 1e-2) would otherwise run for years with no output. Shared by 2D and 3D scenes.
#pragma once

#include <string>
#include <utility>

namespace sim::core {

// the steps of a run from 0 to `until` at `dt` (rounded up)
double stepCount(double dt, double until);

// `count` and `limit` as text, each to 6 significant digits or as many more as tell them apart: a
// run of 100000001 steps read "needs 1e+08 steps, more than the limit of 1e+08"
std::pair<std::string, std::string> distinctCounts(double count, double limit);

// "the run needs 1e+18 steps (1e+06 s at dt = 1e-12 s), more than the limit of 1e+08" when a
// run to `until` at `dt` exceeds `maxSteps`, "" when it does not
std::string stepsOverLimit(double dt, double maxSteps, double until);

// "dt = 10 s is longer than the scene's duration of 1 s: the run would take no step" when dt passes
// a duration above 0 (the world would jump to the end without stepping), "" when it does not
std::string dtOverDuration(double dt, double duration);

}  // namespace sim::core

// Where methods fail: for one method, the largest value of a parameter (the step, a body's speed,
// a mass ratio, a stack's height) at which a scene still holds, found by bisection.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "render/analysis/run_metrics.h"
#include "render/analysis/stability_def.h"
#include "sim/scene/scene_def.h"

namespace render::analysis {

struct StabilityResult {
  // searched for the fewest iterations or substeps that hold (searchFewest): then largestStable is
  // the fewest that held, firstFailing the most that failed, holdsToLimit that the first value tried
  // held already, failsEverywhere that the limit failed too
  bool fewest = false;
  double largestStable = 0.0;  // the largest value that held (0 when none did)
  double firstFailing = 0.0;   // the smallest value found to fail (0 when none did)
  RunMetrics failing;          // the metrics of the run at firstFailing
  bool failsEverywhere = false;
  bool holdsToLimit = false;
  double steps = 0.0;        // the steps of every run of the search together
  bool budgetSpent = false;  // stopped early: the next run would have passed the scene's max_steps
};

// a stability run lasts the scene's duration or this many steps, whichever is longer, so that a
// growing energy can be told from a bounded oscillation even at the largest steps
inline constexpr double kMinimumSteps = 1000.0;
double stabilityDuration(const sim::scene::SceneDef& def);

// the scene with the stability parameter set to `value` (for `speed`, the body starts `phase`
// steps early, so that a search can try where in a step the body meets an obstacle)
Study withParameter(const Study& study, double value, double phase = 0.0);

// does the scene hold at `value`? (for `speed`, at every one of eight phases of the step)
bool holdsAt(const Study& study, double value, RunMetrics& metrics);

// the boundary, by growing and halving to a bracket and then bisecting to 0.1 % of the value, in at
// most the scene's max_steps steps over all its runs
StabilityResult findBoundary(const Study& study);
// the same search for any scene: from `start`, up to `limit`, whole numbers when `integer`;
// `holds(value, metrics)` runs the scene at a value
// thrown by a search's `holds` when the next run would pass its budget of steps: the search stops
// there and says what it knows (StabilityResult::budgetSpent)
struct BudgetSpent {};
// how a search grows a value that holds to find one that fails
enum class Growth { Doubling, ByOne };
StabilityResult searchBoundary(double start, double limit, bool integer, const std::function<bool(double, RunMetrics&)>& holds,
                               Growth growth);
// the fewest (whole) value from `start` up to `limit` at which `holds`, for a scene that holds with
// more effort and fails with less: doubling until one holds, then bisecting down to a neighbour that
// fails
StabilityResult searchFewest(double start, double limit, const std::function<bool(double, RunMetrics&)>& holds);

// "explicit_euler: energy +37 % at dt = 0.021"
std::string describeFailure(const Study& study, const StabilityResult& result);
// the same for any method's label and parameter name
// (`maxSteps`: the budget a search that stopped early names)
std::string describeBoundary(const std::string& method, std::string_view parameter, const StabilityResult& result,
                             double maxSteps = 0.0);

}  // namespace render::analysis

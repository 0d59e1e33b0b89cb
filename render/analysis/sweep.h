// Speed against accuracy: one scene run under many methods and steps, each run measured for its
// cost (wall time per simulated second) and its error, energy drift and deepest penetration.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene_def.h"

namespace render::analysis {

struct SweepCase {
  sim::core::Integrator integrator = sim::core::Integrator::SymplecticEuler;
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;
  double dt = 0.0;
  int iterations = 0;  // sequential velocity iterations
  int substeps = 0;    // soft_step substeps (0: the scene's)
};

// what the error of a run is measured against
struct SweepReference {
  std::string name;                          // "expect", or how the reference run was made
  std::vector<sim::core::BodyState> states;  // the reference run's final states (when not "expect")
};

struct SweepRow {
  SweepCase method;
  long steps = 0;
  double secondsPerSimSecond = 0.0;  // median wall time of `repeat` runs without output
  double error = 0.0;
  double energyDrift = 0.0;
  double maxPenetration = 0.0;
  bool finite = true;
  // processor time of the timed runs per step, median, s: what a stack sweep charts, as it is less
  // disturbed than wall time on a shared machine (a busy neighbour stretches wall time, not processor time)
  double secondsPerStep = 0.0;
  // the stack measures at the end (RunMetrics): the top body's and the farthest body's distance
  // from where they started, m, and the fastest body's speed, m/s
  double topDisplacement = 0.0, maxDisplacement = 0.0, fastest = 0.0;
};

// the scene's expect answers when it has them; otherwise a run with RK4 at a step 64 times smaller
// than `smallestDt`, under the event method where the scene has collisions and it can run
SweepReference sweepReference(const sim::scene::SceneDef& def, double smallestDt);
// a stack's reference: its rest pose, the bodies where they start (error: the top body's displacement)
inline constexpr const char* kRestPose = "rest pose";

// the error of a run: the largest expect error, or the largest distance of a body from the
// reference (its center's, plus its angle times its radius)
SweepRow runSweepCase(const sim::scene::SceneDef& def, const SweepCase& method, const SweepReference& reference, int repeat);

// "FROM:TO:COUNT", log-spaced from FROM to TO; throws UsageError
std::vector<double> parseRange(const std::string& text, const std::string& option);
// COUNT steps log-spaced from FROM to TO
std::vector<double> logRange(double from, double to, int count);
// the steps a sweep tries without --dt: 8 times the scene's dt down to an 8th of it, 7 of them,
// computed from the dt itself (as text with six decimals a dt of 1e-6 became 0)
std::vector<double> defaultSweepSteps(double dt);
// the chart's note when no run has an error above 0 (a force-free body: every method is exact),
// which a log axis cannot show
inline constexpr const char* kAllErrorsZero = "every run's error is exactly 0: nothing to draw on a log scale (see the CSV)";

// a sweep's finest run (its smallest dt, or the reference run at a 64th of it) within the scene's
// bound on steps (sim: max_steps) to `duration`; throws UsageError naming --dt when it is not
void checkSweepSteps(double smallestDt, bool referenceRun, double maxSteps, double duration);

}  // namespace render::analysis

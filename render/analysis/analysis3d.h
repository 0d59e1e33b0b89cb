// Speed against accuracy on 3D scenes: what a run shows about a method (energy and |L| drift,
// | |q| − 1 |, a finite state), the error of a run against the scene's expect answers or a reference
// run, and the largest step at which a 3D scene holds. The 2D analysis' searches and descriptions,
// with the 3D world's measures.
#pragma once

#include <string>
#include <vector>

#include "render/analysis/run_metrics.h"
#include "render/analysis/stability.h"
#include "sim/scene3d/scene_def.h"
#include "sim/world3d/world.h"

namespace sim::yaml {
struct SceneSource;
}

namespace render::analysis {

struct Metrics3dOptions {
  bool energy = true;           // the energy criterion applies (no event or point force feeds it)
  bool angularMomentum = true;  // |L| about the origin must be kept (no external force or torque)
};
// the criteria a scene's run is held to: energy may only grow where nothing feeds it; L only holds
// where nothing outside acts on the bodies
Metrics3dOptions criteria3d(const sim::scene3d::SceneDef& def);

// runs the world to `until` (not started yet), sampling after every step; a divergence ends the
// run and is recorded, not thrown
RunMetrics measureRun3d(sim::world3d::World& world, double until);
// finite; energy trend ≤ 10 %; |L| within 10 % of |L(0)| where it is kept; | |q| − 1 | ≤ 1 %
bool holds3d(RunMetrics& metrics, const Metrics3dOptions& options);

struct Sweep3dRow {
  sim::world3d::Integrator integrator = sim::world3d::Integrator::Splitting;
  double dt = 0.0;
  long steps = 0;
  double secondsPerSimSecond = 0.0;
  double error = 0.0;
  RunMetrics metrics;  // energy, |L| and |q| drift
};

// the scene's expect answers when it has them; otherwise RK4 at a step 64 times smaller than
// `smallestDt` (named "rk4 at dt …", its final states kept)
struct Sweep3dReference {
  std::string name;
  std::vector<sim::world3d::BodyState> states;
};
Sweep3dReference sweepReference3d(const sim::scene3d::SceneDef& def, double smallestDt);
// one case: its error (the largest expect error, or the largest distance of a body from the
// reference: its center's, plus its bounding radius times the angle between the orientations),
// metrics, and the median wall time of `repeat` runs without output
Sweep3dRow runSweepCase3d(const sim::scene3d::SceneDef& def, sim::world3d::Integrator integrator, double dt,
                          const Sweep3dReference& reference, int repeat);

// the stability: block of a 3D scene, which searches `dt` only (nothing collides in 3D); throws
// sim::yaml::SceneError at the fault
StabilityDef readStability3d(const sim::yaml::SceneSource& source);
// the largest dt at which the scene holds under its integrator
StabilityResult findBoundary3d(const sim::scene3d::SceneDef& def, const StabilityDef& stability);

}  // namespace render::analysis

// Another simulator's trajectory against ours: the scene run step by step, each body's state in
// their trace interpolated linearly to each of our steps (any time grid), and per body the largest
// error of position, angle and velocity, when each first exceeds its tolerance, and the kinetic
// energy of each at the end.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/trace/trace_csv.h"
#include "sim/scene/scene_def.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::golden {

struct CompareTolerance {
  double position = 1e-3;  // m
  double angle = 1e-3;     // rad
  double velocity = 1e-2;  // m/s, and rad/s for ω
};

// "position=1e-3,angle=1e-3,velocity=1e-2", any of them, in any order; throws std::invalid_argument
// with what is wrong
CompareTolerance parseCompareTolerance(const std::string& text);

// one quantity of one body: its largest error and when, and when it first exceeded its tolerance
struct ErrorTrack {
  double largest = 0.0, largestAt = 0.0;
  double firstOver = -1.0;  // s, -1 when never
  void add(double error, double t, double tolerance);
};

struct BodyComparison {
  std::string name;
  bool compared = false;  // their trace has rows for it
  ErrorTrack position, angle, velocity;
  double from = 0.0, to = 0.0;                                                         // the times compared, s
  double oursEnergy = 0.0, theirsEnergy = 0.0;                                         // kinetic, J, at the last time compared
  std::vector<std::pair<double, double>> positionErrors, angleErrors, velocityErrors;  // against time, for the chart
  bool exceeded() const { return position.firstOver >= 0.0 || angle.firstOver >= 0.0 || velocity.firstOver >= 0.0; }
};

// the run of `world` (fresh, built from `def`) to the scene's duration against `theirs`; throws
// sim::core::Diverged
std::vector<BodyComparison> compareTrace(const sim::scene::SceneDef& def, sim::world::World& world,
                                         const render::trace::Trace& theirs, const CompareTolerance& tolerance);
// the same of a 3D scene: position and velocity (with ω) in 3D, the angle the rotation between the
// orientations; throws sim::core::Diverged
std::vector<BodyComparison> compareTrace(const sim::scene3d::SceneDef& def, sim::world3d::World& world,
                                         const render::trace::Trace& theirs, const CompareTolerance& tolerance);

}  // namespace render::golden

// What a run shows about a method, for sweeps and stability maps: how much energy it made, how
// deep bodies sank, whether a body went through another, whether a stack drifted, whether the
// state stayed finite.
#pragma once

#include <limits>
#include <vector>

#include "sim/world/world.h"

namespace render::analysis {

struct RunMetrics {
  bool finite = true;
  double divergedAt = std::numeric_limits<double>::quiet_NaN();
  double energyStart = 0.0;
  double energyEnd = 0.0;
  double energyScale = 0.0;     // max(|E(0)|, K(0) + |V(0)|): what drift and trend are relative to
  double energyDrift = 0.0;     // max |E(t) − E(0)| / energyScale
  double energyTrend = 0.0;     // max E over the last third / max E over the first third − 1 (relative
                                // to the scale): growth, told apart from a bounded oscillation
  double maxPenetration = 0.0;  // deepest overlap at any step end, m
  bool tunneled = false;        // a body ended up through another, with no contact on the way
  int tunnelA = -1, tunnelB = -1;
  double topDrift = 0.0;  // the highest dynamic body's displacement over its size
  // at the end of a finite run, against where the dynamic bodies started (their rest pose in a
  // stack): the highest one's displacement and the largest of any, m, and the fastest speed, m/s
  double topDisplacement = 0.0;
  double maxDisplacement = 0.0;
  double fastest = 0.0;
  long steps = 0;
  // 3D runs (analysis3d.h): the largest |L(t) − L(0)| / |L(0)| about the origin, and | |q| − 1 |
  double angularMomentumDrift = 0.0;
  double quaternionDrift = 0.0;
  const char* failure = "";  // the first criterion that failed, or "" (see holds())
};

struct MetricsOptions {
  bool penetration = true;  // find contacts after every step (costly for big scenes)
  bool energy = true;       // the energy criterion applies (no source of energy in the scene)
  bool stack = false;       // the stack-drift criterion applies
  // when positive, a stack holds only if every dynamic body ends within this distance of where it
  // started, m, and slower than kRestSpeed (the "holding": within 5 cm and below 1 cm/s)
  double within = 0.0;
};

// a body slower than this at the end is at rest, m/s (the `within` criterion)
inline constexpr double kRestSpeed = 0.01;

// the run's energy at the start, E(0) = kinetic + potential, and the scale drifts are relative to
void startEnergy(double kinetic, double potential, RunMetrics& metrics);
// the drift and the trend of the energies after every step (E(0) set by startEnergy)
void summarizeEnergies(const std::vector<double>& energies, RunMetrics& metrics);

// runs the world to `until` (it must not have started), recording the metrics step by step;
// a divergence ends the run and is recorded, not thrown
RunMetrics measureRun(sim::world::World& world, double until, const MetricsOptions& options);

// the stability criteria: finite; energy trend ≤ 10 %; no tunneling; top of a stack drifting less
// than 5 % of its size; every body within `within` of its start and at rest (when asked);
// penetration under 2 × slop. Fills metrics.failure with the first that fails.
bool holds(RunMetrics& metrics, const MetricsOptions& options);

}  // namespace render::analysis

#include "render/analysis/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "render/analysis/interrupt_check.h"
#include "render/analysis/run_metrics.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/json_writer.h"
#include "sim/core/step_limit.h"
#include "sim/scene/expect.h"
#include "sim/scene/scene_build.h"

namespace render::analysis {
using namespace render::jobs;

namespace {

// an entry that checks a law over the whole run (energy_never_rises), not a value: no error to chart
bool lawOnly(const sim::scene::ExpectDef& e) { return e.energyNeverRises; }

sim::scene::SceneDef withMethod(sim::scene::SceneDef def, const SweepCase& m) {
  // the error is the distance from the closed forms' values (the energy ledger's rise is no distance)
  std::erase_if(def.expects, lawOnly);
  def.integrator = m.integrator;
  def.collisions = m.collisions;
  def.dt = m.dt;
  if (m.iterations > 0) def.velocityIterations = m.iterations;
  if (m.substeps > 0) def.substeps = m.substeps;
  return def;
}

// whether the scene's bodies can collide at all (auto resolves to none otherwise)
bool hasCollisions(const sim::scene::SceneDef& def) {
  sim::world::World w = sim::scene::buildWorld(def);
  w.start();
  return w.collisions() != sim::core::CollisionMethod::None;
}

}  // namespace

SweepReference sweepReference(const sim::scene::SceneDef& def, double smallestDt) {
  if (!std::all_of(def.expects.begin(), def.expects.end(), lawOnly)) return {"expect", {}};
  SweepCase ref{sim::core::Integrator::Rk4, def.collisions, smallestDt / 64.0, 0};
  std::string name = "rk4 at dt " + formatNumber(ref.dt);
  // the exact event method is the reference where bodies collide and it can run the scene
  if (hasCollisions(def)) {
    ref.collisions = sim::core::CollisionMethod::Event;
    try {
      sim::world::World w = sim::scene::buildWorld(withMethod(def, ref));
      InterruptCheck stop;
      w.advanceTo(def.duration, &stop);
      SweepReference out{"event, " + name, {}};
      for (const sim::core::Body& b : w.bodies) out.states.push_back(b.state());
      return out;
    } catch (const render::jobs::Interrupted&) {
      throw;
    } catch (const std::exception&) {
      ref.collisions = def.collisions;  // event cannot run it (overlap, pile-up): the scene's method
    }
  }
  sim::world::World w = sim::scene::buildWorld(withMethod(def, ref));
  InterruptCheck stop;
  w.advanceTo(def.duration, &stop);
  SweepReference out{name, {}};
  for (const sim::core::Body& b : w.bodies) out.states.push_back(b.state());
  return out;
}

SweepRow runSweepCase(const sim::scene::SceneDef& scene, const SweepCase& method, const SweepReference& reference, int repeat) {
  const sim::scene::SceneDef def = withMethod(scene, method);
  SweepRow row;
  row.method = method;

  // the measured run: error, energy, penetration
  sim::world::World w = sim::scene::buildWorld(def);
  MetricsOptions options;
  options.penetration = def.bodies.size() > 1;
  const RunMetrics m = measureRun(w, def.duration, options);
  row.method.collisions = w.collisions();
  row.steps = w.steps;
  row.finite = m.finite;
  row.energyDrift = m.energyDrift;
  row.maxPenetration = m.maxPenetration;
  row.topDisplacement = m.topDisplacement;
  row.maxDisplacement = m.maxDisplacement;
  row.fastest = m.fastest;
  if (!m.finite) {
    row.error = std::numeric_limits<double>::infinity();
  } else if (reference.name == kRestPose) {
    row.error = m.topDisplacement;
  } else if (reference.name == "expect") {
    sim::world::World again = sim::scene::buildWorld(def);
    InterruptCheck stop;
    for (const sim::core::CheckResult& r : sim::scene::runExpects(def, again, &stop)) row.error = std::max(row.error, r.error);
  } else {
    for (size_t i = 0; i < w.bodies.size(); ++i) {
      const sim::core::Body& b = w.bodies[i];
      if (b.isStatic) continue;
      const sim::core::BodyState& r = reference.states[i];
      const double arm = sim::core::boundingRadius(b.shape);
      row.error = std::max(row.error, std::hypot((b.x - r.x).norm(), arm * (b.angle - r.angle)));
    }
  }

  // the timed runs: nothing but the simulation
  std::vector<double> seconds, processor;
  InterruptCheck stop;
  for (int k = 0; k < repeat && m.finite; ++k) {
    sim::world::World timed = sim::scene::buildWorld(def);
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    timed.advanceTo(def.duration, &stop);
    processor.push_back(static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  if (!seconds.empty()) {
    std::sort(seconds.begin(), seconds.end());
    row.secondsPerSimSecond = seconds[seconds.size() / 2] / def.duration;
    std::sort(processor.begin(), processor.end());
    row.secondsPerStep = processor[processor.size() / 2] / static_cast<double>(std::max(1L, row.steps));
  }
  return row;
}

std::vector<double> parseRange(const std::string& text, const std::string& option) {
  // COUNT read as a number and checked before it becomes an int: sscanf's %d past int's range is
  // undefined behavior
  double from = 0.0, to = 0.0, counted = 0.0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf:%lf:%lf%c", &from, &to, &counted, &tail) != 3 || !(from > 0.0) || !(to > 0.0) ||
      !std::isfinite(from) || !std::isfinite(to) || !(counted >= 1.0 && counted <= 1000.0) || counted != std::floor(counted))
    throw UsageError(option + ": expected FROM:TO:COUNT with positive FROM and TO and a COUNT from 1 to 1000, got '" + text +
                     "'");
  return logRange(from, to, static_cast<int>(counted));
}

std::vector<double> logRange(double from, double to, int count) {
  std::vector<double> values;
  for (int k = 0; k < count; ++k)
    values.push_back(count == 1 ? from : from * std::pow(to / from, static_cast<double>(k) / (count - 1)));
  return values;
}

std::vector<double> defaultSweepSteps(double dt) { return logRange(dt * 8, dt / 8, 7); }

void checkSweepSteps(double smallestDt, bool referenceRun, double maxSteps, double duration) {
  // the reference is a 64th of the smallest step (sweepReference, sweepReference3d)
  const double finest = referenceRun ? smallestDt / 64.0 : smallestDt;
  if (const std::string over = sim::core::stepsOverLimit(finest, maxSteps, duration); !over.empty())
    throw UsageError(std::string("--dt: ") + (referenceRun ? "the reference run at a 64th of the smallest dt: " : "") + over +
                     "; choose a larger smallest dt, or raise the limit with sim: {max_steps: N} in the scene");
}

}  // namespace render::analysis

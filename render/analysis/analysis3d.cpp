#include "render/analysis/analysis3d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "render/analysis/interrupt_check.h"
#include "sim/scene3d/expect.h"
#include "sim/scene3d/scene_build.h"
#include "sim/world3d/diagnostics.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/yaml_reader.h"

namespace render::analysis {
using namespace sim::world;
namespace w3 = sim::world3d;

namespace {

class Recorder3d : public w3::StepObserver {
 public:
  Recorder3d(RunMetrics& m, const w3::Vec3& l0) : m_(m), l0_(l0) {}
  void afterStep(const w3::World& w) override {
    render::jobs::checkInterrupted();
    ++m_.steps;
    energies.push_back(energy(w).total());
    // relative to |L(0)|, or absolute when the bodies start without angular momentum
    const double scale = std::max(l0_.norm(), 1e-300);
    m_.angularMomentumDrift = std::max(m_.angularMomentumDrift, (angularMomentum(w) - l0_).norm() / scale);
    m_.quaternionDrift = std::max(m_.quaternionDrift, quaternionDrift(w));
  }
  std::vector<double> energies;

 private:
  RunMetrics& m_;
  w3::Vec3 l0_;
};

sim::scene3d::SceneDef withMethod(sim::scene3d::SceneDef def, w3::Integrator integrator, double dt) {
  def.integrator = integrator;
  def.dt = dt;
  return def;
}

// the angle between two orientations, rad: the rotation q_ref⁻¹ q, whatever their signs and lengths
double angleBetween(const w3::Quat& q, const w3::Quat& reference) {
  const w3::Quat d = reference.conjugate() * q;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

}  // namespace

Metrics3dOptions criteria3d(const sim::scene3d::SceneDef& def) {
  Metrics3dOptions o;
  o.energy = def.events.empty() && def.pointForces.empty();
  bool anchored = false;
  for (const sim::scene3d::SpringDef& s : def.springs) anchored = anchored || s.body2.empty();
  o.angularMomentum = o.energy && def.gravity == w3::Vec3::Zero() && def.drags.empty() && !anchored;
  return o;
}

RunMetrics measureRun3d(w3::World& world, double until) {
  RunMetrics m;
  const w3::Energy e0 = energy(world);
  startEnergy(e0.kinetic, e0.potential, m);
  Recorder3d recorder(m, angularMomentum(world));
  try {
    world.advanceTo(until, &recorder);
  } catch (const sim::core::Diverged& d) {
    m.finite = false;
    m.divergedAt = d.time;
  }
  m.energyEnd = energy(world).total();
  summarizeEnergies(recorder.energies, m);
  return m;
}

bool holds3d(RunMetrics& m, const Metrics3dOptions& o) {
  // a tenth of |L| or of E, a hundredth of |q|: far beyond round-off and a method's truncation on a
  // scene it resolves, and well before a picture turns wrong
  if (!m.finite) m.failure = "non-finite state";
  else if (o.energy && (!std::isfinite(m.energyTrend) || m.energyTrend > 0.10)) m.failure = "energy grows";
  else if (o.angularMomentum && !(m.angularMomentumDrift <= 0.10)) m.failure = "angular momentum drifts";
  else if (!(m.quaternionDrift <= 0.01)) m.failure = "quaternion drifts";
  else m.failure = "";
  return *m.failure == '\0';
}

Sweep3dReference sweepReference3d(const sim::scene3d::SceneDef& def, double smallestDt) {
  if (!def.expects.empty()) return {"expect", {}};
  const double dt = smallestDt / 64.0;
  w3::World w = sim::scene3d::buildWorld(withMethod(def, w3::Integrator::Rk4, dt));
  InterruptCheck3d stop;
  w.advanceTo(def.duration, &stop);
  char name[64];
  std::snprintf(name, sizeof name, "rk4 at dt %g", dt);
  Sweep3dReference out{name, {}};
  for (const w3::Body& b : w.bodies) out.states.push_back(b.state());
  return out;
}

Sweep3dRow runSweepCase3d(const sim::scene3d::SceneDef& scene, w3::Integrator integrator, double dt,
                          const Sweep3dReference& reference, int repeat) {
  const sim::scene3d::SceneDef def = withMethod(scene, integrator, dt);
  Sweep3dRow row;
  row.integrator = integrator;
  row.dt = dt;
  w3::World w = sim::scene3d::buildWorld(def);
  row.metrics = measureRun3d(w, def.duration);
  row.steps = w.steps;
  if (!row.metrics.finite) {
    row.error = std::numeric_limits<double>::infinity();
  } else if (reference.name == "expect") {
    w3::World again = sim::scene3d::buildWorld(def);
    InterruptCheck3d stop;
    for (const sim::core::CheckResult& r : sim::scene3d::runExpects(def, again, &stop)) row.error = std::max(row.error, r.error);
  } else {
    for (size_t i = 0; i < w.bodies.size(); ++i) {
      const w3::Body& b = w.bodies[i];
      const w3::BodyState& r = reference.states[i];
      row.error = std::max(row.error, (b.x - r.x).norm() + w3::boundingRadius(b.shape) * angleBetween(b.q, r.q));
    }
  }
  // the timed runs: nothing but the simulation
  std::vector<double> seconds;
  InterruptCheck3d stop;
  for (int k = 0; k < repeat && row.metrics.finite; ++k) {
    w3::World timed = sim::scene3d::buildWorld(def);
    const auto start = std::chrono::steady_clock::now();
    timed.advanceTo(def.duration, &stop);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  if (!seconds.empty()) {
    std::sort(seconds.begin(), seconds.end());
    row.secondsPerSimSecond = seconds[seconds.size() / 2] / def.duration;
  }
  return row;
}

StabilityDef readStability3d(const sim::yaml::SceneSource& source) {
  const YAML::Node n = source.root[kStabilityKey];
  if (n && n.IsMap() && n["parameter"])
    sim::yaml::readGuarded(source.file, [&] {
      const sim::yaml::Reader r(source.file);
      if (r.text(n["parameter"], "parameter") != "dt")
        r.fail(n["parameter"],
               "a 3D scene's stability searches 'dt' only: nothing collides in 3D, so no speed, mass "
               "ratio or stack height breaks it");
    });
  // the block as 2D reads it; with parameter dt it names no body
  return readStability(source, sim::scene::SceneDef{});
}

StabilityResult findBoundary3d(const sim::scene3d::SceneDef& def, const StabilityDef& stability) {
  const Metrics3dOptions o = criteria3d(def);
  return searchBoundary(
      stability.from > 0.0 ? stability.from : def.dt, stability.to > 0.0 ? stability.to : 1e12, false,
      [&](double dt, RunMetrics& m) {
        sim::scene3d::SceneDef at = def;
        at.dt = dt;
        w3::World w = sim::scene3d::buildWorld(at);
        // as in 2D: the scene's duration or 1000 steps, whichever is longer
        m = measureRun3d(w, std::max(at.duration, kMinimumSteps * dt));
        return holds3d(m, o);
      },
      Growth::Doubling);
}

}  // namespace render::analysis

#include "render/golden/trace_compare.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "render/jobs/interrupt.h"
#include "render/golden/sample3d.h"
#include "sim/world/diagnostics.h"
#include "sim/world3d/diagnostics.h"

namespace render::golden {
using namespace render::trace;

namespace {

// the most points of a chart's series: every step of a long run would be a million
constexpr size_t kChartPoints = 2000;

// one body of ours against their sample at the same time: the errors, and both kinetic energies
struct Errors {
  double position, angle, velocity, ours, theirs;
};

Errors errorsOf(const sim::core::Body& b, const TraceSample& s) {
  // theirs as their trace gives it, else from their velocities and our mass and inertia
  return {std::hypot(b.x.x() - s.x, b.x.y() - s.y), std::abs(b.angle - s.angle),
          std::max(std::hypot(b.v.x() - s.vx, b.v.y() - s.vy), std::abs(b.omega - s.omega)), sim::world::kineticEnergy(b).total(),
          s.kineticEnergy != 0.0 || b.isStatic
              ? s.kineticEnergy
              : 0.5 * b.mass * (s.vx * s.vx + s.vy * s.vy) + 0.5 * b.inertia * s.omega * s.omega};
}

Errors errorsOf(const sim::world3d::Body& b, const TraceSample& s) {
  const TraceSample ours = sampleOf(b, s.t);
  // theirs, when their trace leaves it out, from their velocities and our mass and inertia
  sim::world3d::Body moving = b;
  moving.v = {s.vx, s.vy, s.vz}, moving.omega = {s.wx, s.wy, s.omega};
  return {std::hypot(ours.x - s.x, ours.y - s.y, ours.z - s.z), rotationBetween(ours, s),
          std::max(std::hypot(ours.vx - s.vx, ours.vy - s.vy, ours.vz - s.vz),
                   std::hypot(ours.wx - s.wx, ours.wy - s.wy, ours.omega - s.omega)),
          ours.kineticEnergy, s.kineticEnergy != 0.0 ? s.kineticEnergy : sim::world3d::kineticEnergy(moving).total()};
}

// the run's steps compared with their trace, in 2D (sim::world) or 3D (sim::world3d)
template <class Def, class World, class Observer, class Event>
class Comparer : public Observer {
 public:
  Comparer(const Def& def, const Trace& theirs, const CompareTolerance& tolerance)
      : theirs_(theirs), tolerance_(tolerance), bodies_(def.bodies.size()) {
    for (size_t i = 0; i < def.bodies.size(); ++i) {
      bodies_[i].name = def.bodies[i].name;
      bodies_[i].compared = !theirs.bodies[i].empty();
    }
    const double steps = def.duration / def.dt;
    every_ = std::max<long>(1, static_cast<long>(steps / kChartPoints));
  }
  // after a step, their row before an event at that time; after an event, the row after it; and
  // Ctrl-C honoured between two steps
  void afterStep(const World& w) override {
    render::jobs::checkInterrupted();
    compare(w, true, ++steps_ % every_ == 0);
  }
  void afterEvent(const World& w, const Event&) override { compare(w, false, false); }
  void compare(const World& w, bool before, bool chart) {
    for (size_t i = 0; i < bodies_.size(); ++i) {
      BodyComparison& c = bodies_[i];
      TraceSample s;
      if (!c.compared || !sampleAt(theirs_.bodies[i], w.time, s, before)) continue;
      const Errors e = errorsOf(w.bodies[i], s);
      if (c.positionErrors.empty()) c.from = w.time;
      c.position.add(e.position, w.time, tolerance_.position);
      c.angle.add(e.angle, w.time, tolerance_.angle);
      c.velocity.add(e.velocity, w.time, tolerance_.velocity);
      c.to = w.time;
      c.oursEnergy = e.ours;
      c.theirsEnergy = e.theirs;
      if (chart || c.positionErrors.empty()) {
        c.positionErrors.emplace_back(w.time, e.position);
        c.angleErrors.emplace_back(w.time, e.angle);
        c.velocityErrors.emplace_back(w.time, e.velocity);
      }
    }
  }
  std::vector<BodyComparison> result() { return std::move(bodies_); }

 private:
  const Trace& theirs_;
  CompareTolerance tolerance_;
  std::vector<BodyComparison> bodies_;
  long steps_ = 0, every_ = 1;
};

}  // namespace

void ErrorTrack::add(double error, double t, double tolerance) {
  if (error > largest || std::isnan(error)) largest = error, largestAt = t;
  if (firstOver < 0.0 && !(error <= tolerance)) firstOver = t;
}

CompareTolerance parseCompareTolerance(const std::string& text) {
  CompareTolerance t;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    double* target = key == "position" ? &t.position : key == "angle" ? &t.angle : key == "velocity" ? &t.velocity : nullptr;
    if (eq == std::string::npos || !target)
      throw std::invalid_argument("expected position=X,angle=X,velocity=X (any of them), got '" + item + "'");
    size_t used = 0;
    double v = -1.0;
    try {
      v = std::stod(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() - eq - 1 || !(v >= 0.0) || !std::isfinite(v))
      throw std::invalid_argument("'" + key + "' needs a tolerance of zero or more, got '" + item.substr(eq + 1) + "'");
    *target = v;
  }
  return t;
}

namespace {

template <class Def, class World, class Observer, class Event>
std::vector<BodyComparison> compareRun(const Def& def, World& world, const Trace& theirs, const CompareTolerance& tolerance) {
  Comparer<Def, World, Observer, Event> comparer(def, theirs, tolerance);
  // the first state too, before any step
  comparer.compare(world, true, true);
  world.advanceTo(def.duration, &comparer);
  return comparer.result();
}

}  // namespace

std::vector<BodyComparison> compareTrace(const sim::scene::SceneDef& def, sim::world::World& world, const Trace& theirs,
                                         const CompareTolerance& tolerance) {
  return compareRun<sim::scene::SceneDef, sim::world::World, sim::world::StepObserver, sim::world::ImpulseEvent>(
      def, world, theirs, tolerance);
}

std::vector<BodyComparison> compareTrace(const sim::scene3d::SceneDef& def, sim::world3d::World& world, const Trace& theirs,
                                         const CompareTolerance& tolerance) {
  return compareRun<sim::scene3d::SceneDef, sim::world3d::World, sim::world3d::StepObserver, sim::world3d::ImpulseEvent>(
      def, world, theirs, tolerance);
}

}  // namespace render::golden

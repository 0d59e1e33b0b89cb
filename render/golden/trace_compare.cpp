#include "render/golden/trace_compare.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "render/jobs/interrupt.h"
#include "sim/world/diagnostics.h"

namespace render::golden {

namespace {

// the most points of a chart's series: every step of a long run would be a million
constexpr size_t kChartPoints = 2000;

class Comparer : public sim::world::StepObserver {
 public:
  Comparer(const sim::scene::SceneDef& def, const Trace& theirs, const CompareTolerance& tolerance)
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
  void afterStep(const sim::world::World& w) override {
    render::jobs::checkInterrupted();
    compare(w, true, ++steps_ % every_ == 0);
  }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent&) override { compare(w, false, false); }
  void compare(const sim::world::World& w, bool before, bool chart) {
    for (size_t i = 0; i < bodies_.size(); ++i) {
      BodyComparison& c = bodies_[i];
      TraceSample s;
      if (!c.compared || !sampleAt(theirs_.bodies[i], w.time, s, before)) continue;
      const sim::core::Body& b = w.bodies[i];
      const double position = std::hypot(b.x.x() - s.x, b.x.y() - s.y);
      const double angle = std::abs(b.angle - s.angle);
      const double velocity = std::max(std::hypot(b.v.x() - s.vx, b.v.y() - s.vy), std::abs(b.omega - s.omega));
      if (c.positionErrors.empty()) c.from = w.time;
      c.position.add(position, w.time, tolerance_.position);
      c.angle.add(angle, w.time, tolerance_.angle);
      c.velocity.add(velocity, w.time, tolerance_.velocity);
      c.to = w.time;
      c.oursEnergy = sim::world::kineticEnergy(b).total();
      // theirs as their trace gives it, else from their velocities and our mass and inertia
      c.theirsEnergy = s.kineticEnergy != 0.0 || b.isStatic
                           ? s.kineticEnergy
                           : 0.5 * b.mass * (s.vx * s.vx + s.vy * s.vy) + 0.5 * b.inertia * s.omega * s.omega;
      if (chart || c.positionErrors.empty()) {
        c.positionErrors.emplace_back(w.time, position);
        c.angleErrors.emplace_back(w.time, angle);
        c.velocityErrors.emplace_back(w.time, velocity);
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

std::vector<BodyComparison> compareTrace(const sim::scene::SceneDef& def, sim::world::World& world, const Trace& theirs,
                                         const CompareTolerance& tolerance) {
  Comparer comparer(def, theirs, tolerance);
  // the first state too, before any step
  comparer.compare(world, true, true);
  world.advanceTo(def.duration, &comparer);
  return comparer.result();
}

}  // namespace render::golden

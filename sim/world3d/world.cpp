#include "sim/world3d/world.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace sim::world3d {

Diverged::Diverged(double t, int b)
    : std::runtime_error("body " + std::to_string(b) + "'s state is no longer finite at t = " + std::to_string(t)),
      time(t),
      body(b) {}

void World::start() {
  if (started_) return;
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("the time step dt must be a positive finite number");
  pending_ = events;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const ImpulseEvent& a, const ImpulseEvent& b) { return a.time < b.time; });
  std::vector<double> instants = forces.breakpoints();
  for (const ImpulseEvent& e : pending_) instants.push_back(e.time);
  grid_ = sim::core::StepGrid(dt, std::move(instants));
  started_ = true;
}

void World::advanceTo(double tEnd, StepObserver* observer) {
  start();
  applyDueEvents(observer);
  while (time < tEnd && !grid_.same(time, tEnd)) stepTo(grid_.nextStop(time, tEnd), tEnd, observer);
  time = std::max(time, tEnd);
}

void World::advanceWithin(double t, double tEnd, StepObserver* observer) {
  start();
  applyDueEvents(observer);
  while (time < tEnd && !grid_.same(time, tEnd)) {
    const double stop = grid_.nextStop(time, tEnd);
    if (stop > t && !grid_.same(stop, t)) break;
    stepTo(stop, tEnd, observer);
  }
}

// one step from now to `stop` on the way to tEnd, the events due there applied
void World::stepTo(double stop, double tEnd, StepObserver* observer) {
  step(stop - time);
  time = grid_.arrive(stop, tEnd);
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite();
  if (observer) observer->afterStep(*this);
  applyDueEvents(observer);
}

// one step of size h: the integrator on every body's state, then (by default) back onto unit
// quaternions
void World::step(double h) {
  scratch_.assign(bodies.begin(), bodies.end());
  // the timed forces that are on somewhere inside the step are on for all of it (it is split at
  // every switch)
  const Dynamics dynamics{bodies, forces, time + 0.5 * h};
  integrate(integrator, dynamics, h, scratch_);
  if (normalizeQuaternions) normalizeRotations(scratch_);
  for (size_t i = 0; i < bodies.size(); ++i) bodies[i].setState(scratch_[i]);
  ++steps;
}

void World::applyDueEvents(StepObserver* observer) {
  // every event up to now: events before the start of the run are applied at its start
  while (nextEvent_ < pending_.size() && (pending_[nextEvent_].time < time || grid_.same(pending_[nextEvent_].time, time))) {
    const ImpulseEvent& e = pending_[nextEvent_++];
    Body& b = bodies[e.body];
    b.applyImpulse(e.pointInWorld ? e.point : b.toWorld(e.point), e.impulse);
    if (observer) observer->afterEvent(*this, e);
  }
}

void World::checkFinite() const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !isFinite(b.q) || !isFinite(b.v) || !isFinite(b.omega)) throw Diverged(time, static_cast<int>(i));
  }
}

}  // namespace sim::world3d

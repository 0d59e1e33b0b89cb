#include "world.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace sim {

Diverged::Diverged(double t, int b)
    : std::runtime_error("state is no longer finite at t = " + std::to_string(t)), time(t), body(b) {}

void World::applyImpulse(int i, const Vec2& r, const Vec2& j) {
  Body& b = bodies[i];
  b.v += b.invMass * j;
  b.omega += b.invInertia * cross(r - b.x, j);
}

void World::rates(double, const States& y, Rates& out) const {
  forces.accumulate(window_, bodies, y, force_, torque_);
  out.resize(y.size());
  for (size_t i = 0; i < y.size(); ++i) {
    const Body& b = bodies[i];
    if (b.isStatic) {
      out[i] = BodyRate{};
      continue;
    }
    out[i] = {y[i].v, y[i].omega, b.invMass * force_[i], b.invInertia * torque_[i]};
  }
}

void World::start() {
  pending_ = events;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const ImpulseEvent& a, const ImpulseEvent& b) { return a.time < b.time; });
  switches_ = forces.breakpoints();
  std::sort(switches_.begin(), switches_.end());
  started_ = true;
}

// the next time to stop at: the next grid point, event, force switch or the end, whichever is first
double World::nextStop(double tEnd) const {
  double stop = std::min(tEnd, (gridIndex_ + 1) * dt);
  if (nextEvent_ < pending_.size()) stop = std::min(stop, pending_[nextEvent_].time);
  auto sw = std::upper_bound(switches_.begin(), switches_.end(), time + settings::kTimeSnap * dt);
  if (sw != switches_.end()) stop = std::min(stop, *sw);
  return stop;
}

void World::advanceTo(double tEnd, StepObserver* observer) {
  if (!started_) start();
  applyDueEvents(observer);
  while (time < tEnd - settings::kTimeSnap * dt) {
    const double stop = nextStop(tEnd);
    const double grid = (gridIndex_ + 1) * dt;
    step(stop - time);
    // land on the grid point itself when the stop is (within round-off) the grid point
    if (std::abs(stop - grid) <= settings::kTimeSnap * dt) {
      ++gridIndex_;
      time = std::abs(stop - tEnd) <= settings::kTimeSnap * dt ? tEnd : grid;
    } else {
      time = stop;
    }
    if (observer) observer->afterStep(*this);
    applyDueEvents(observer);
  }
  time = std::max(time, tEnd);
}

// one step of size h: the stages of the notes' free-body dynamics
void World::step(double h) {
  // integrate forces and torques over the step with the chosen integrator
  window_ = time + 0.5 * h;
  scratch_.resize(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) scratch_[i] = bodies[i].state();
  integrate(integrator, *this, time, h, scratch_);
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].isStatic) bodies[i].setState(scratch_[i]);
  ++steps;
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite(time + h);
}

void World::applyDueEvents(StepObserver* observer) {
  while (nextEvent_ < pending_.size() && pending_[nextEvent_].time <= time + settings::kTimeSnap * dt) {
    const ImpulseEvent& e = pending_[nextEvent_++];
    const Body& b = bodies[e.body];
    const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
    applyImpulse(e.body, r, e.impulse);
    if (observer) observer->afterEvent(*this, e);
  }
}

void World::checkFinite(double t) const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !std::isfinite(b.angle) || !isFinite(b.v) || !std::isfinite(b.omega))
      throw Diverged(t, static_cast<int>(i));
  }
}

}  // namespace sim

#include "sim/world/energy_ledger.h"

#include <algorithm>
#include <cmath>

#include "sim/world/diagnostics.h"

namespace sim::world {
using sim::core::ForcePower;

EnergyLedger::EnergyLedger(const World& world, StepObserver* next)
    : next_(next), time_(world.time), impacts_(world.impacts.size()) {
  const Energy e = energy(world);
  start = end = e.total();
  scale = std::abs(e.kinetic) + std::abs(e.potential);
  adjusted_ = lowest_ = start;
  if (world.forces.hasWorkingForces()) states_ = world.states();
}

std::pair<int, int> EnergyLedger::where(const World& world, size_t impactsBefore) {
  if (impactsBefore < world.impacts.size()) return {world.impacts[impactsBefore].a, world.impacts[impactsBefore].b};
  if (!world.contacts.empty()) return {world.contacts.front().a, world.contacts.front().b};
  return {-1, -1};
}

void EnergyLedger::afterStep(const World& world) {
  const Energy e = energy(world);
  const double h = world.time - time_;
  // the work of the forces without a potential over the step, with the forces on during it (those on
  // at its midpoint): the point forces' by how far their points moved (exact for a force fixed in the
  // world), the damping's by the trapezoid rule on its power at the step's two ends
  ForcePower work;
  if (!states_.empty()) {
    const double window = time_ + 0.5 * h;
    const States now = world.states();
    work.applied = world.forces.pointForceWork(window, states_, now);
    work.damping = 0.5 * h * (world.forces.power(window, states_).damping + world.forces.power(window, now).damping);
    appliedWork += work.applied;
    lostToDamping -= work.damping;
  }
  // what is left of the change: the collision response's, or the integrator's
  const double residual = e.total() - end - work.applied - work.damping;
  const auto [a, b] = where(world, impacts_);
  if (residual > 0.0) {
    gained += residual;
    if (residual > largestGain.amount) largestGain = {world.time, residual, a, b};
  } else if (impacts_ < world.impacts.size()) {
    lostAtImpacts -= residual;
  } else if (a >= 0) {
    lostInContacts -= residual;
  } else {
    lostByIntegrator -= residual;
  }
  adjusted_ += e.total() - end - work.applied;
  impacts_ = world.impacts.size();
  observe(world);
  if (next_) next_->afterStep(world);
}

void EnergyLedger::afterEvent(const World& world, const ImpulseEvent& event) {
  // an event's impulse does its work at one instant: its change of E, exactly
  const double e = energy(world).total();
  eventWork += e - end;
  observe(world);
  if (next_) next_->afterEvent(world, event);
}

// the state now becomes the last observation: the energy, its scale, the adjusted energy's rise
void EnergyLedger::observe(const World& world) {
  const Energy e = energy(world);
  end = e.total();
  time_ = world.time;
  scale = std::max(scale, std::abs(e.kinetic) + std::abs(e.potential));
  if (!states_.empty()) states_ = world.states();
  lowest_ = std::min(lowest_, adjusted_);
  const double rise = adjusted_ - lowest_;
  const auto [a, b] = where(world, world.impacts.size());
  if (rise > largestRise_.amount) largestRise_ = {world.time, rise, a, b};
  for (Watched& w : watched_)
    if (!w.first && rise > w.tolerance) w.first = EnergyRise{world.time, rise, a, b};
}

std::optional<EnergyRise> EnergyLedger::firstRiseAbove(double tolerance) const {
  for (const Watched& w : watched_)
    if (w.tolerance == tolerance) return w.first;
  return std::nullopt;
}

}  // namespace sim::world

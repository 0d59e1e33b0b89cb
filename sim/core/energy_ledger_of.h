// The energy ledger of a run, alike in 2D and 3D: where the energy E = ½mv² + ½Iω² + U (the notes' kinetic energy, and
// the potentials of gravity and springs) went, step by step. Each step's change of E, less the work
// the forces without a potential did over it (applied point forces in: f · Δr of their points;
// drags and damped springs out: the trapezoid rule on their power) and the work of the impulse events
// at its end (their change of E, exactly), leaves the collision response's share and the
// integrator's error. That residual goes to one account: lost at the step's impacts, lost in its
// contacts (friction and plastic settling between impacts), lost by the integration of free motion,
// or, when it is positive, gained, with when and where. The accounts add up to E's change.
//
// It also keeps the adjusted energy E − (work of applied forces and events), which a run that only
// loses energy never raises: `expect: {energy_never_rises: true, tolerance}` is checked against its
// rise above its lowest value so far, at every step.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "sim/core/check_result.h"

namespace sim::core {

// a rise of the energy: when, how much, and between which bodies (-1: in free motion, the
// integrator's; a pair: at or in its contact, b in 3D a plane when negative)
struct EnergyRise {
  double time = 0.0;
  double amount = 0.0;  // J
  int a = -1, b = -1;
};

// the ledger of a world of either dimension: World has bodies, time, forces (hasWorkingForces,
// pointForceWork, power), states(), impacts and contacts (each with a and b), and `energy(world)`
// (found by argument-dependent lookup) gives its kinetic and potential energy
template <class World, class Observer, class Event, class States>
class EnergyLedgerOf : public Observer {
 public:
  // from the world's state now; `next`, if any, sees every step and event after the ledger
  explicit EnergyLedgerOf(const World& world, Observer* next = nullptr)
      : next_(next), time_(world.time), impacts_(world.impacts.size()) {
    const auto e = energy(world);
    start = end = e.total();
    scale = std::abs(e.kinetic) + std::abs(e.potential);
    adjusted_ = lowest_ = start;
    if (world.def().forces.hasWorkingForces()) states_ = world.states();
  }

  void afterStep(const World& world) override {
    const auto e = energy(world);
    const double h = world.time - time_;
    // the work of the forces without a potential over the step, with the forces on during it (those on
    // at its midpoint): the point forces' by how far their points moved (exact for a force fixed in the
    // world), the damping's by the trapezoid rule on its power at the step's two ends
    double applied = 0.0, damping = 0.0;
    if (!states_.empty()) {
      const double window = time_ + 0.5 * h;
      const States now = world.states();
      applied = world.def().forces.pointForceWork(window, states_, now);
      damping = 0.5 * h * (world.def().forces.power(window, states_).damping + world.def().forces.power(window, now).damping);
      appliedWork += applied;
      lostToDamping -= damping;
    }
    // what is left of the change: the collision response's, or the integrator's
    const double residual = e.total() - end - applied - damping;
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
    adjusted_ += e.total() - end - applied;
    impacts_ = world.impacts.size();
    observe(world);
    if (next_) next_->afterStep(world);
  }

  void afterEvent(const World& world, const Event& event) override {
    // an event's impulse does its work at one instant: its change of E, exactly
    eventWork += energy(world).total() - end;
    observe(world);
    if (next_) next_->afterEvent(world, event);
  }

  // the accounts, J (losses positive)
  double start = 0.0, end = 0.0;  // E at the start and now
  double lostAtImpacts = 0.0;
  double lostInContacts = 0.0;
  double lostToDamping = 0.0;
  double lostByIntegrator = 0.0;
  double appliedWork = 0.0;  // of the point forces
  double eventWork = 0.0;    // of the impulse events
  double gained = 0.0;       // every step's rise beyond the work done on the bodies
  EnergyRise largestGain;    // the largest rise of one step
  // the largest of E's magnitudes over the run, J: the scale round-off is measured against
  double scale = 0.0;

  // the adjusted energy's largest rise above its lowest value so far, and when
  EnergyRise largestRise() const { return largestRise_; }
  // the first time the adjusted energy rose above its lowest so far by more than `tolerance`, with
  // the rise then; none while it has not (watch the tolerance before the run: watch(tolerance))
  void watch(double tolerance) { watched_.push_back({tolerance, std::nullopt}); }
  std::optional<EnergyRise> firstRiseAbove(double tolerance) const {
    for (const Watched& w : watched_)
      if (w.tolerance == tolerance) return w.first;
    return std::nullopt;
  }

 private:
  // the bodies' pair of the step's first impact, else of its first contact, else none
  static std::pair<int, int> where(const World& world, size_t impactsBefore) {
    if (impactsBefore < world.impacts.size()) return {world.impacts[impactsBefore].a, world.impacts[impactsBefore].b};
    if (!world.contacts.empty()) return {world.contacts.front().a, world.contacts.front().b};
    return {-1, -1};
  }

  // the state now becomes the last observation: the energy, its scale, the adjusted energy's rise
  void observe(const World& world) {
    const auto e = energy(world);
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

  Observer* next_;
  double time_ = 0.0;
  States states_;  // at the last observation, for the work over the next step (only with working forces)
  size_t impacts_ = 0;
  double adjusted_ = 0.0, lowest_ = 0.0;
  EnergyRise largestRise_;
  struct Watched {
    double tolerance;
    std::optional<EnergyRise> first;
  };
  std::vector<Watched> watched_;
};

// `energy_never_rises` checked on a ledger of the run up to `time` (`snap`: a time within it is
// `time`): at the first step the adjusted energy rose above its lowest by more than `tolerance`,
// with the rise then and where (`nameOf(i)`: a body's or, in 3D, a plane's name), else its largest
// rise, which passes
template <class Ledger, class NameOf>
CheckResult neverRisesResult(const Ledger& ledger, double time, double tolerance, double snap, bool earlierRun, NameOf nameOf) {
  const std::optional<EnergyRise> first = ledger.firstRiseAbove(tolerance);
  const bool failed = first && first->time <= time + snap;
  const EnergyRise r = failed ? *first : ledger.largestRise();
  std::string quantity = "energy_never_rises";
  if (failed)
    quantity += r.a < 0 ? " (rose in free motion: the integrator's)"
                        : " (rose at the contact of '" + nameOf(r.a) + "' and '" + nameOf(r.b) + "')";
  CheckResult result = compareValues(failed ? r.time : time, tolerance, quantity, {0.0}, {r.amount});
  result.earlierRun = earlierRun;
  return result;
}

}  // namespace sim::core

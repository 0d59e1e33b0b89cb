// The energy ledger of a run: where the energy E = ½mv² + ½Iω² + U (the notes' kinetic energy, and
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

#include <optional>
#include <vector>

#include "sim/world/world.h"

namespace sim::world {

// a rise of the energy: when, how much, and between which bodies (-1: in free motion, the
// integrator's; a pair: at or in its contact)
struct EnergyRise {
  double time = 0.0;
  double amount = 0.0;  // J
  int a = -1, b = -1;
};

class EnergyLedger : public StepObserver {
 public:
  // from the world's state now; `next`, if any, sees every step and event after the ledger
  explicit EnergyLedger(const World& world, StepObserver* next = nullptr);

  void afterStep(const World& world) override;
  void afterEvent(const World& world, const ImpulseEvent& event) override;

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
  std::optional<EnergyRise> firstRiseAbove(double tolerance) const;

 private:
  void observe(const World& world);
  // the bodies' pair of the step's first impact, else of its first contact, else none
  static std::pair<int, int> where(const World& world, size_t impactsBefore);

  StepObserver* next_;
  double time_ = 0.0;
  States states_;  // at the last observation, for the power at a step's start (only with working forces)
  size_t impacts_ = 0;
  double adjusted_ = 0.0, lowest_ = 0.0;
  EnergyRise largestRise_;
  struct Watched {
    double tolerance;
    std::optional<EnergyRise> first;
  };
  std::vector<Watched> watched_;
};

}  // namespace sim::world

// What a run tells whoever watches it (a trace, a ledger, a history of what to draw): every
// finished step and every applied impulse event, the same in 2D and 3D.
#pragma once

namespace sim::core {

template <class World, class Event>
class StepObserverOf {
 public:
  virtual ~StepObserverOf() = default;
  virtual void afterStep(const World&) {}
  virtual void afterEvent(const World&, const Event&) {}
};

}  // namespace sim::core

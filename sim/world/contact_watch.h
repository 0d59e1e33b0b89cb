// `auto`'s watch over the event method: a contact that persists is one the event method does not
// model (it ends a Zeno series of bounces in frictionless resting contact, and every bounce of a
// rattling pair costs a time-of-impact search), so the run goes on under the resting-contact solver
// from the end of the step in which the watch saw it (World::step). Two signs, whichever comes
// first: the event method turned a contact resting (a body at rest on another, or sliding on it);
// one pair's slow impacts repeat within a short window (a box rocking on its corners). A pair that
// stays touching over consecutive steps under the event method does one of the two: it strikes
// again at each step, or the method made it resting.
#pragma once

#include <optional>

#include "sim/core/collision_methods.h"
#include "sim/core/rattle_watch.h"

namespace sim::world {

class World;

struct PersistentContact {
  sim::core::Persistence how = sim::core::Persistence::Rested;
  int a = 0, b = 0;
};

class ContactWatch {
 public:
  // after one step of the event method, which recorded the world's impacts from `impactsBefore`
  // and its resting contacts from `restingBefore` on: the contact that persists, if any
  std::optional<PersistentContact> afterStep(const World& world, size_t impactsBefore, size_t restingBefore);

 private:
  std::optional<PersistentContact> rattling(const World& world, size_t impactsBefore);

  sim::core::RattleWatch rattle_;
};

}  // namespace sim::world

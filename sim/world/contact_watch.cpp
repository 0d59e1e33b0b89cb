#include "sim/world/contact_watch.h"

#include <algorithm>

#include "sim/world/world.h"

namespace sim::world {
using sim::core::Persistence;
using namespace sim::core;

std::optional<PersistentContact> ContactWatch::afterStep(const World& world, size_t impactsBefore, size_t restingBefore) {
  // the event method itself found a pair too slow to part (its Zeno end)
  if (world.resting.size() > restingBefore) {
    const RestingRecord& r = world.resting[restingBefore];
    return PersistentContact{Persistence::Rested, r.a, r.b};
  }
  return rattling(world, impactsBefore);
}

// slow impacts of one pair at kRepeatedImpacts instants within kRepeatWindow (points struck at one
// instant, a box landing flat, count once)
std::optional<PersistentContact> ContactWatch::rattling(const World& world, size_t impactsBefore) {
  for (size_t k = impactsBefore; k < world.impacts.size(); ++k) {
    const ImpactRecord& r = world.impacts[k];
    if (rattle_.impact(r.a, r.b, r.t, r.vnBefore, settings::kTouchingTolerance * world.sceneSize()))
      return PersistentContact{Persistence::Rattling, r.a, r.b};
  }
  return std::nullopt;
}

}  // namespace sim::world

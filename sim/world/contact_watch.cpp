#include "sim/world/contact_watch.h"

#include <algorithm>

#include "sim/world/world.h"

namespace sim::world {
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
    std::vector<double>& times = instants_[{r.a, r.b}];
    if (-r.vnBefore > settings::kRepeatSpeed) {
      times.clear();
      continue;
    }
    if (!times.empty() && r.t - times.back() <= settings::kTouchingTolerance * world.sceneSize()) continue;
    times.push_back(r.t);
    std::erase_if(times, [&](double t) { return r.t - t > settings::kRepeatWindow; });
    if (static_cast<int>(times.size()) >= settings::kRepeatedImpacts) return PersistentContact{Persistence::Rattling, r.a, r.b};
  }
  return std::nullopt;
}

}  // namespace sim::world

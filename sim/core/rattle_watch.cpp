#include "sim/core/rattle_watch.h"

#include <algorithm>

#include "sim/core/settings.h"

namespace sim::core {

bool RattleWatch::impact(int a, int b, double t, double vnBefore, double sameInstant) {
  std::vector<double>& times = instants_[{a, b}];
  // a fast impact is a bounce: the pair starts over
  if (-vnBefore > settings::kRepeatSpeed) {
    times.clear();
    return false;
  }
  if (!times.empty() && t - times.back() <= sameInstant) return false;
  times.push_back(t);
  std::erase_if(times, [&](double s) { return t - s > settings::kRepeatWindow; });
  return static_cast<int>(times.size()) >= settings::kRepeatedImpacts;
}

}  // namespace sim::core

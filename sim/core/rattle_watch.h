// One sign that a contact persists, alike in 2D and 3D: a pair whose slow impacts come again and
// again within a short window rattles rather than bounces (a box rocking on its corners), which
// the event method answers one search at a time and does not bring to rest (settings.h:
// kRepeatedImpacts, kRepeatWindow, kRepeatSpeed).
#pragma once

#include <map>
#include <utility>
#include <vector>

namespace sim::core {

class RattleWatch {
 public:
  // one impact of the pair (a, b) at time t with normal velocity vnBefore (< 0: approaching);
  // impacts within `sameInstant` of the pair's last are one (points struck together, a box landing
  // flat). True when this one makes the pair's slow impacts persist.
  bool impact(int a, int b, double t, double vnBefore, double sameInstant);

 private:
  // each pair's recent slow impact instants (within the window)
  std::map<std::pair<int, int>, std::vector<double>> instants_;
};

}  // namespace sim::core

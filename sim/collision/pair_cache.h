// The broad phase kept from step to step (Box2D's fat boxes: b2DynamicTree's enlarged AABBs and
// its pair buffer). Each box is enlarged by kBroadPhaseExtension where it is placed, and the pairs
// whose enlarged boxes overlap are kept as candidates; a call finds the overlapping pairs among the
// candidates. Only a box that left its enlarged box (or grew much smaller than it) is placed anew
// and paired against all the others; when many did, the grid pairs the boxes for a few calls and
// then all are placed anew (through the grid). The
// candidates hold every overlapping pair, so the pairs are exactly overlappingPairs' (broad_phase.h),
// in the same order; a pile at rest costs a few tests per box instead of a grid a step.
#pragma once

#include <utility>
#include <vector>

#include "sim/collision/collide.h"

namespace sim::collision {

class PairCache {
 public:
  // overlappingPairs(boxes, fixed), into `pairs` (cleared first)
  void find(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed, std::vector<std::pair<int, int>>& pairs);

 private:
  void placeAll(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed);
  void placeMoved(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed);

  std::vector<Aabb> enlarged_;              // each box as placed, enlarged
  std::vector<std::vector<int>> partners_;  // the candidates of each box, of lower and higher index, sorted
  std::vector<int> moved_;                  // scratch: the boxes to place anew this call
  std::vector<char> state_;                 // scratch: 0 kept, 1 to place anew, 2 placed anew
  std::vector<char> changed_;               // scratch: a box whose candidates changed this call
  int gridCalls_ = 0;                       // calls left to pair through the grid alone (boxes scatter)
  int gridCallsNext_ = 1;                   // how many, the next time they scatter
};

}  // namespace sim::collision

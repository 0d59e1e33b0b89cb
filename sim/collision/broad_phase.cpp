#include "sim/collision/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace sim::collision {
using namespace sim::core;

std::vector<std::pair<int, int>> overlappingPairs(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed) {
  // sweep along x: after sorting by the lower x bound, a box can only meet the boxes that start
  // before it ends
  std::vector<int> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return boxes[i].lower.x() < boxes[j].lower.x() || (boxes[i].lower.x() == boxes[j].lower.x() && i < j);
  });
  std::vector<std::pair<int, int>> pairs;
  for (size_t p = 0; p < order.size(); ++p) {
    const int i = order[p];
    for (size_t q = p + 1; q < order.size(); ++q) {
      const int j = order[q];
      if (boxes[j].lower.x() > boxes[i].upper.x()) break;
      if (fixed[i] && fixed[j]) continue;
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace sim::collision

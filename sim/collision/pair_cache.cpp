#include "sim/collision/pair_cache.h"

#include <algorithm>

#include "sim/collision/broad_phase.h"
#include "sim/core/settings.h"

namespace sim::collision {
using sim::core::Vec2;
using namespace sim::core;

namespace {

// more boxes than this to place anew: all of them through the grid (each placed alone is tested
// against every box; the grid costs about as much as a hundred of those)
constexpr size_t kMaxPlacedAlone = 64;

// while boxes scatter, the grid pairs them for at most this many calls before they are placed again
constexpr int kMaxGridCalls = 32;

Aabb enlarge(const Aabb& box, double by) { return {box.lower - Vec2::Constant(by), box.upper + Vec2::Constant(by)}; }

bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lower.x() <= inner.lower.x() && outer.lower.y() <= inner.lower.y() && inner.upper.x() <= outer.upper.x() &&
         inner.upper.y() <= outer.upper.y();
}

void erase(std::vector<int>& list, int value) {
  const auto it = std::find(list.begin(), list.end(), value);
  if (it != list.end()) *it = list.back(), list.pop_back();
}

}  // namespace

void PairCache::find(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed, std::vector<std::pair<int, int>>& pairs) {
  const size_t n = boxes.size();
  // a box is placed anew when it left its enlarged box, or when that is much larger than it (a
  // call with a wider margin than the next): a NaN box always
  constexpr double e = settings::kBroadPhaseExtension;
  if (gridCalls_ > 0) {
    --gridCalls_;
    pairs = overlappingPairs(boxes, fixed);
    return;
  }
  moved_.clear();
  if (enlarged_.size() == n)
    for (size_t i = 0; i < n; ++i)
      if (!contains(enlarged_[i], boxes[i]) || !contains(enlarge(boxes[i], 2.0 * e), enlarged_[i]))
        moved_.push_back(static_cast<int>(i));
  if (enlarged_.size() == n && moved_.size() > kMaxPlacedAlone) {
    // many boxes left their enlarged ones since the last call (a pile scattering): placing them all
    // anew would cost a grid every call and gain nothing, so the grid pairs the boxes themselves
    // for the next calls, twice as many each time this happens again (Box2D has no such case: its
    // tree moves each box alone)
    enlarged_.clear();
    gridCalls_ = gridCallsNext_;
    gridCallsNext_ = std::min(2 * gridCallsNext_, kMaxGridCalls);
    pairs = overlappingPairs(boxes, fixed);
    return;
  }
  if (enlarged_.size() != n) {
    placeAll(boxes, fixed);
  } else {
    gridCallsNext_ = 1;
    if (!moved_.empty()) placeMoved(boxes, fixed);
  }
  // the candidates that overlap now, each pair once (at its lower index) and in order (each box's
  // candidates kept sorted: they change only when a box is placed anew)
  // (a box's higher candidates found by bisection: a pile at rest holds about eight per box, half
  // of them lower)
  pairs.clear();
  for (size_t ii = 0; ii < n; ++ii) {
    const int i = static_cast<int>(ii);
    const bool fixedI = fixed[i];
    const std::vector<int>& partners = partners_[i];
    for (auto j = std::upper_bound(partners.begin(), partners.end(), i); j != partners.end(); ++j)
      if (!(fixedI && fixed[*j]) && boxes[i].overlaps(boxes[*j])) pairs.emplace_back(i, *j);
  }
}

void PairCache::placeAll(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed) {
  const size_t n = boxes.size();
  enlarged_.resize(n);
  for (size_t i = 0; i < n; ++i) enlarged_[i] = enlarge(boxes[i], settings::kBroadPhaseExtension);
  partners_.resize(n);
  for (std::vector<int>& p : partners_) p.clear();
  // (the pairs come sorted, so each box's list is: its lower partners, then its higher, in order)
  for (const auto& [i, j] : overlappingPairs(enlarged_, fixed)) {
    partners_[i].push_back(j);
    partners_[j].push_back(i);
  }
}

void PairCache::placeMoved(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed) {
  const size_t n = boxes.size();
  state_.assign(n, 0);
  changed_.assign(n, 0);
  for (int i : moved_) {
    state_[i] = 1;
    enlarged_[i] = enlarge(boxes[i], settings::kBroadPhaseExtension);
    for (int j : partners_[i]) erase(partners_[j], i), changed_[j] = 1;
    partners_[i].clear();
  }
  // each moved box against every box; a pair of two moved boxes once, by the first of them
  for (int i : moved_) {
    for (size_t jj = 0; jj < n; ++jj) {
      const int j = static_cast<int>(jj);
      if (j == i || state_[j] == 2 || (fixed[i] && fixed[j]) || !enlarged_[i].overlaps(enlarged_[j])) continue;
      partners_[i].push_back(j);
      partners_[j].push_back(i);
      changed_[j] = 1;
    }
    state_[i] = 2;
  }
  // the lists that changed, sorted again: a moved box's, and its old and new partners'
  for (size_t j = 0; j < n; ++j)
    if (state_[j] != 0 || changed_[j]) std::sort(partners_[j].begin(), partners_[j].end());
}

}  // namespace sim::collision

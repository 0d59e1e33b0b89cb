#include "sim/collision/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace sim::collision {
using namespace sim::core;

namespace {

using Pair = std::pair<int, int>;

// the pairs of `candidates` (any order, each once) sorted by (i, j): counted into one bucket per
// i, then each bucket's few j sorted, so the cost is linear in the pairs
std::vector<Pair> sortedPairs(const std::vector<Pair>& candidates, size_t bodies) {
  std::vector<int> start(bodies + 1, 0);
  for (const Pair& p : candidates) ++start[p.first + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Pair> out(candidates.size());
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const Pair& p : candidates) out[next[p.first]++] = p;
  for (size_t i = 0; i < bodies; ++i)
    if (start[i + 1] - start[i] > 1) std::sort(out.begin() + start[i], out.begin() + start[i + 1]);
  return out;
}

// sweep along x: after sorting by the lower x bound, a box can only meet the boxes that start
// before it ends (Ericson 7.5.2); used for few boxes, or many large ones
void sweep(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed, std::vector<Pair>& pairs) {
  std::vector<int> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return boxes[i].lower.x() < boxes[j].lower.x() || (boxes[i].lower.x() == boxes[j].lower.x() && i < j);
  });
  for (size_t p = 0; p < order.size(); ++p) {
    const int i = order[p];
    for (size_t q = p + 1; q < order.size(); ++q) {
      const int j = order[q];
      if (boxes[j].lower.x() > boxes[i].upper.x()) break;
      if (fixed[i] && fixed[j]) continue;
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
}

// a box's extent: its larger side (infinite or NaN for a plane's unbounded box)
double extentOf(const Aabb& b) { return std::max(b.upper.x() - b.lower.x(), b.upper.y() - b.lower.y()); }

// Uniform grid (Ericson 7.1, hashed): cells as wide as the largest "small" box, so a small box
// covers at most 2 × 2 cells and meets only the boxes in its cells; the few boxes larger than that
// (the ground, planes) are tested against every box. A pair is reported only in the cell that
// holds the lower corner of the two boxes' overlap, so once. Linear in the boxes and the pairs,
// where the sweep along x meets, in a pile, every box of every row above and below.
struct GridEntry {
  std::int64_t cx, cy;
  int box;
};
// the grid's working storage, kept per thread from call to call: a pile's broad phase then
// allocates nothing (fresh pages for these cost a pile of 5,050 boxes about as much as the grid)
struct GridScratch {
  std::vector<double> extents, sorted;
  std::vector<int> large, start, next;
  std::vector<char> isLarge;
  std::vector<GridEntry> entries, byBucket;
  std::vector<size_t> bucket;
};
thread_local GridScratch scratch;

bool grid(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed, std::vector<Pair>& pairs) {
  const size_t n = boxes.size();
  std::vector<double>& extents = scratch.extents;
  extents.resize(n);
  for (size_t i = 0; i < n; ++i) extents[i] = extentOf(boxes[i]);
  std::vector<double>& sorted = scratch.sorted;
  sorted = extents;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end(),
                   [](double a, double b) { return a < b || (!std::isnan(a) && std::isnan(b)); });
  const double median = sorted[n / 2];
  if (!(median > 0.0 && std::isfinite(median))) return false;
  // the cell: the largest box within 8 times the median extent; larger ones are tested against all
  double cell = 0.0;
  std::vector<int>& large = scratch.large;
  large.clear();
  for (size_t i = 0; i < n; ++i) {
    if (extents[i] <= 8.0 * median) cell = std::max(cell, extents[i]);
    else large.push_back(static_cast<int>(i));
  }
  if (large.size() > 64) return false;
  // cell coordinates, bounded so that far-flung boxes still have integer cells
  const auto cellOf = [cell](double v) { return static_cast<std::int64_t>(std::floor(std::clamp(v / cell, -1e15, 1e15))); };
  using Entry = GridEntry;
  std::vector<Entry>& entries = scratch.entries;
  entries.clear();
  std::vector<char>& isLarge = scratch.isLarge;
  isLarge.assign(n, 0);
  for (int i : large) isLarge[i] = 1;
  for (size_t i = 0; i < n; ++i) {
    if (isLarge[i]) continue;
    const std::int64_t x0 = cellOf(boxes[i].lower.x()), x1 = cellOf(boxes[i].upper.x());
    const std::int64_t y0 = cellOf(boxes[i].lower.y()), y1 = cellOf(boxes[i].upper.y());
    for (std::int64_t cx = x0; cx <= x1; ++cx)
      for (std::int64_t cy = y0; cy <= y1; ++cy) entries.push_back({cx, cy, static_cast<int>(i)});
  }
  // hashed into buckets by counting (a bucket may hold several cells: entries compare their cells)
  size_t tableSize = 1;
  while (tableSize < 2 * entries.size()) tableSize <<= 1;
  const auto bucketOf = [tableSize](const Entry& e) {
    const std::uint64_t h =
        static_cast<std::uint64_t>(e.cx) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(e.cy) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>((h ^ (h >> 29)) & (tableSize - 1));
  };
  std::vector<int>& start = scratch.start;
  start.assign(tableSize + 1, 0);
  std::vector<size_t>& bucket = scratch.bucket;
  bucket.resize(entries.size());
  for (size_t k = 0; k < entries.size(); ++k) ++start[(bucket[k] = bucketOf(entries[k])) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Entry>& byBucket = scratch.byBucket;
  byBucket.resize(entries.size());
  std::vector<int>& next = scratch.next;
  next.assign(start.begin(), start.end() - 1);
  for (size_t k = 0; k < entries.size(); ++k) byBucket[next[bucket[k]]++] = entries[k];
  for (size_t t = 0; t < tableSize; ++t)
    for (int p = start[t]; p < start[t + 1]; ++p)
      for (int q = p + 1; q < start[t + 1]; ++q) {
        const Entry &e = byBucket[p], &f = byBucket[q];
        if (e.cx != f.cx || e.cy != f.cy) continue;
        const int i = e.box, j = f.box;
        if ((fixed[i] && fixed[j]) || !boxes[i].overlaps(boxes[j])) continue;
        // only in the cell of the overlap's lower corner
        if (cellOf(std::max(boxes[i].lower.x(), boxes[j].lower.x())) != e.cx ||
            cellOf(std::max(boxes[i].lower.y(), boxes[j].lower.y())) != e.cy)
          continue;
        pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
  // the large boxes against every box (a pair of two large ones once)
  for (int i : large)
    for (size_t jj = 0; jj < n; ++jj) {
      const int j = static_cast<int>(jj);
      if (j == i || (isLarge[j] && j < i) || (fixed[i] && fixed[j])) continue;
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  return true;
}

}  // namespace

std::vector<std::pair<int, int>> overlappingPairs(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed) {
  std::vector<Pair> pairs;
  // a grid pays from a few dozen boxes on; below, or with many large boxes, the sweep
  if (boxes.size() < 64 || !grid(boxes, fixed, pairs)) {
    pairs.clear();
    sweep(boxes, fixed, pairs);
  }
  return sortedPairs(pairs, boxes.size());
}

}  // namespace sim::collision

#include "sim/collision/pair_cache.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "sim/collision/broad_phase.h"
#include "sim/core/settings.h"

namespace {

using Pairs = std::vector<std::pair<int, int>>;
using sim::collision::Aabb;
using sim::core::Vec2;

// every pair i < j whose boxes overlap (touching counts), except two fixed boxes: by definition
Pairs bruteForce(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed) {
  Pairs pairs;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (!(fixed[i] && fixed[j]) && boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

}  // namespace

// boxes that drift a little (kept candidates), jump (placed alone), all jump at once (placed
// through the grid), shrink or widen with the margin, and turn NaN: each call's pairs are the
// brute-force ones, in order
TEST_CASE("PairCache finds exactly the overlapping pairs, call after call, however the boxes move") {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e = sim::core::settings::kBroadPhaseExtension;
  for (int n : {0, 1, 40, 300}) {
    CAPTURE(n);
    std::vector<Vec2> lower(n), size(n);
    std::vector<bool> fixed(n);
    for (int i = 0; i < n; ++i) {
      lower[i] = {12.0 * u(rng), 12.0 * u(rng)};
      size[i] = {0.5 + u(rng), 0.5 + u(rng)};
      fixed[i] = u(rng) < 0.2;
    }
    sim::collision::PairCache cache;
    Pairs got;
    size_t seen = 0;
    for (int call = 0; call < 60; ++call) {
      CAPTURE(call);
      // most boxes creep by less than the extension; a few jump; every tenth call all of them do
      for (int i = 0; i < n; ++i) {
        const double step = call % 10 == 9 ? 3.0 : (u(rng) < 0.05 ? 1.0 : 0.3 * e);
        if (!fixed[i]) lower[i] += Vec2(step * (u(rng) - 0.5), step * (u(rng) - 0.5));
      }
      // the margin: as the solvers' (small), wider than the extension, or unbounded
      const double margin = call % 7 == 3 ? 3.0 * e : (call % 13 == 5 ? std::numeric_limits<double>::infinity() : 0.01);
      std::vector<Aabb> boxes(n);
      for (int i = 0; i < n; ++i) boxes[i] = {lower[i] - Vec2::Constant(margin), lower[i] + size[i] + Vec2::Constant(margin)};
      if (n > 0 && call % 11 == 4) boxes[n / 2].lower.x() = std::nan("");
      cache.find(boxes, fixed, got);
      const Pairs expected = bruteForce(boxes, fixed);
      CHECK(got == expected);
      seen += expected.size();
    }
    if (n >= 40) CHECK(seen > static_cast<size_t>(10 * n));
  }
}

TEST_CASE("PairCache: the same pairs as overlappingPairs for a floor and a row of boxes") {
  std::vector<Aabb> boxes{{{-1, -1}, {110, 0}}};
  std::vector<bool> fixed{true};
  for (int i = 0; i < 100; ++i) {
    boxes.push_back({{1.05 * i, 0.0}, {1.05 * i + 1.0, 1.0}});
    fixed.push_back(false);
  }
  sim::collision::PairCache cache;
  Pairs got;
  cache.find(boxes, fixed, got);
  CHECK(got == sim::collision::overlappingPairs(boxes, fixed));
  CHECK(got.size() == 100);
  // the boxes close up sideways by less than the extension: the kept candidates hold the new pairs
  for (size_t i = 1; i < boxes.size(); ++i) boxes[i].upper.x() += 0.06;
  cache.find(boxes, fixed, got);
  CHECK(got == sim::collision::overlappingPairs(boxes, fixed));
  CHECK(got.size() == 199);
}

#include "sim/collision/broad_phase.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace {

using Pairs = std::vector<std::pair<int, int>>;

// every pair i < j whose boxes overlap (touching counts), except two fixed boxes: by definition
Pairs bruteForce(const std::vector<sim::collision::Aabb>& boxes, const std::vector<bool>& fixed) {
  Pairs pairs;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (!(fixed[i] && fixed[j]) && boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

// a plane's bounds as the world computes them: unbounded, or bounded on one side when axis-aligned
sim::collision::Aabb planeBox(const sim::core::Vec2& normal, const sim::core::Vec2& point) {
  return sim::collision::bounds(sim::core::makePlane(normal), {point, sim::core::Rot{}});
}

}  // namespace

TEST_CASE("bounds of a plane: axis-aligned half-planes are bounded on one side, oblique ones not at all") {
  const double inf = std::numeric_limits<double>::infinity();
  const sim::collision::Aabb floor = planeBox({0, 1}, {0, 2});
  CHECK(floor.lower == sim::core::Vec2(-inf, -inf));
  CHECK(floor.upper == sim::core::Vec2(inf, 2));
  const sim::collision::Aabb wall = planeBox({-1, 0}, {3, 0});
  CHECK(wall.lower == sim::core::Vec2(3, -inf));
  CHECK(wall.upper == sim::core::Vec2(inf, inf));
  const sim::collision::Aabb slope = planeBox({1, 1}, {0, 0});
  CHECK(slope.lower == sim::core::Vec2(-inf, -inf));
  CHECK(slope.upper == sim::core::Vec2(inf, inf));
}

// n random boxes, planes and static bodies; on a coarse grid (`onGrid`) boxes share edges and lower
// bounds exactly (ties in the sort, touching boxes, zero-size boxes); `large` of them up to 40 wide
void randomBoxes(std::mt19937_64& rng, int n, bool onGrid, int large, std::vector<sim::collision::Aabb>& boxes,
                 std::vector<bool>& fixed) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double r = u(rng);
    if (r < 0.08) {
      // a half-plane: floor, ceiling, walls or an oblique one, always static
      const sim::core::Vec2 normals[] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}, {0.6, 0.8}};
      const sim::core::Vec2 normal = normals[static_cast<int>(u(rng) * 5.0)];
      boxes.push_back(planeBox(normal, {20.0 * u(rng) - 10.0, 20.0 * u(rng) - 10.0}));
      fixed.push_back(true);
      continue;
    }
    sim::core::Vec2 lower, size;
    if (onGrid) {
      lower = {std::floor(10.0 * u(rng)) - 5.0, std::floor(10.0 * u(rng)) - 5.0};
      size = {std::floor(4.0 * u(rng)), std::floor(4.0 * u(rng))};
    } else {
      lower = {20.0 * u(rng) - 10.0, 20.0 * u(rng) - 10.0};
      size = {4.0 * u(rng), 4.0 * u(rng)};
    }
    if (i < large) size *= 10.0;
    boxes.push_back({lower, lower + size});
    fixed.push_back(u(rng) < 0.3);
  }
}

// overlappingPairs against brute force over `trials` random sets of n(trial) boxes; how many
// pairs and overlapping static pairs (which must be left out) the comparison saw
std::pair<size_t, size_t> compareWithBruteForce(std::mt19937_64& rng, int trials, int minBoxes, int maxBoxes, int large) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  size_t totalPairs = 0, skippedStatic = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const int n = minBoxes + static_cast<int>(u(rng) * (maxBoxes - minBoxes));
    std::vector<sim::collision::Aabb> boxes;
    std::vector<bool> fixed;
    randomBoxes(rng, n, trial % 3 == 0, trial % 2 == 0 ? large : 0, boxes, fixed);
    const Pairs expected = bruteForce(boxes, fixed);
    const Pairs got = sim::collision::overlappingPairs(boxes, fixed);
    CAPTURE(trial);
    CAPTURE(n);
    CHECK(got == expected);
    // sorted, i < j, no pair twice
    CHECK(std::is_sorted(got.begin(), got.end()));
    CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
    for (const auto& [i, j] : got) CHECK(i < j);
    totalPairs += expected.size();
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) skippedStatic += fixed[i] && fixed[j] && boxes[i].overlaps(boxes[j]);
  }
  return {totalPairs, skippedStatic};
}

TEST_CASE("overlappingPairs equals brute-force all-pairs overlap on random boxes, planes and static bodies") {
  std::mt19937_64 rng(1618);
  // few boxes (the sweep)
  const auto [totalPairs, skippedStatic] = compareWithBruteForce(rng, 400, 0, 60, 0);
  CHECK(totalPairs > 1000);
  CHECK(skippedStatic > 100);
  // many (the grid), with a few large boxes among them, and with more large ones than the grid
  // takes (back to the sweep)
  const auto [gridPairs, gridStatic] = compareWithBruteForce(rng, 40, 64, 600, 5);
  CHECK(gridPairs > 10000);
  CHECK(gridStatic > 1000);
  compareWithBruteForce(rng, 4, 200, 300, 100);
}

TEST_CASE("overlappingPairs: small cases by hand") {
  // nothing, one box
  CHECK(sim::collision::overlappingPairs({}, {}).empty());
  CHECK(sim::collision::overlappingPairs({{{0, 0}, {1, 1}}}, {false}).empty());
  // touching edges and corners overlap; a gap does not; the list is in index order whatever the x order
  const std::vector<sim::collision::Aabb> boxes{{{2, 0}, {3, 1}}, {{1, 0}, {2, 1}}, {{3, 1}, {4, 2}}, {{0, 5}, {9, 6}}};
  CHECK(sim::collision::overlappingPairs(boxes, {false, false, false, false}) == Pairs{{0, 1}, {0, 2}});
  // two static boxes never pair; static with dynamic does
  CHECK(sim::collision::overlappingPairs(boxes, {true, true, false, false}) == Pairs{{0, 2}});
  // a static floor (unbounded below and sideways) pairs with every dynamic box reaching down to it
  std::vector<sim::collision::Aabb> withFloor = boxes;
  withFloor.push_back(planeBox({0, 1}, {0, 1}));
  CHECK(sim::collision::overlappingPairs(withFloor, {false, false, false, false, true}) ==
        Pairs{{0, 1}, {0, 2}, {0, 4}, {1, 4}, {2, 4}});
}

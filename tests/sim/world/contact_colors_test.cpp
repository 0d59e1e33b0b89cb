// Graph colouring of contacts (contact_colors.cpp): no two contacts of a colour share a body that
// moves, every contact is in exactly one colour or the overflow, and the greedy order is the input's.
#include <doctest/doctest.h>

#include <random>
#include <set>
#include <vector>

#include "sim/world/contact_colors.h"

using sim::world::ColoredPair;
using sim::world::ContactColors;

TEST_CASE("contact colours: random pairs among 50 bodies, some static: no moving body twice in a colour, each contact once") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> body(0, 49);
  std::vector<ColoredPair> pairs;
  for (int i = 0; i < 600; ++i) {
    const int a = body(rng), b = body(rng);
    if (a == b) continue;
    pairs.push_back({a, b, a < 5, b < 5});  // bodies 0-4 are static
  }
  ContactColors colors;
  colorContacts(pairs, 50, colors);
  std::vector<int> seen(pairs.size(), 0);
  for (const std::vector<int>& color : colors.sets) {
    REQUIRE_FALSE(color.empty());
    std::set<int> moving;
    for (int i : color) {
      ++seen[i];
      for (const auto& [index, isStatic] : {std::pair{pairs[i].a, pairs[i].aStatic}, std::pair{pairs[i].b, pairs[i].bStatic}}) {
        if (isStatic) continue;
        CHECK(moving.insert(index).second);
      }
    }
    // in input order within a colour
    for (size_t k = 1; k < color.size(); ++k) CHECK(color[k - 1] < color[k]);
  }
  for (int i : colors.overflow) ++seen[i];
  for (size_t i = 0; i < pairs.size(); ++i) CHECK(seen[i] == 1);
  CHECK(colors.overflow.empty());  // no body is in 64 contacts here
}

TEST_CASE("contact colours: a body in more than 64 contacts sends the rest to the overflow; a static body shares colours") {
  std::vector<ColoredPair> pairs;
  for (int i = 1; i <= 70; ++i) pairs.push_back({0, i, false, false});
  for (int i = 1; i <= 70; ++i) pairs.push_back({71, i, true, false});  // body 71 static
  ContactColors colors;
  colorContacts(pairs, 72, colors);
  CHECK(colors.sets.size() == 64);
  CHECK(colors.overflow == std::vector<int>{64, 65, 66, 67, 68, 69});
  // contact 0-i took colour i-1; the static contacts of body i then take colour 0 where it is free
  // of body i (every i but 1) and colour 1 for body 1
  CHECK(colors.sets[0].size() == 70);
  CHECK(colors.sets[1].size() == 2);
}

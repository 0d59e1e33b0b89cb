// Graph colouring of contact constraints (Box2D v3's constraint graph; Catto, "Solver2D" and
// "SIMD Matters", 2024): the contacts are split into sets such that no two contacts of a set
// share a body that moves. The contacts of one set change disjoint bodies, so they can be solved
// side by side (in SIMD lanes, on two threads) with the same result as one after the other.
#pragma once

#include <cstdint>
#include <vector>

namespace sim::world {

// one contact's two bodies; a static body never counts (nothing writes to it)
struct ColoredPair {
  int a = 0, b = 0;
  bool aStatic = false, bStatic = false;
};

struct ContactColors {
  static constexpr int kMaxColors = 64;  // one bit per set in a body's mask
  // the contacts of each set, in the order of the input
  std::vector<std::vector<int>> sets;
  // contacts of a body that is already in kMaxColors sets: solved one after the other, first
  std::vector<int> overflow;
};

// greedy colouring in input order: each contact takes the lowest set neither of its moving
// bodies has yet (the order of the input fixes the sets, so the result is deterministic)
void colorContacts(const std::vector<ColoredPair>& pairs, int bodyCount, ContactColors& out);

}  // namespace sim::world

#include "sim/world/contact.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

double combinedRestitution(double a, double b) { return std::max(a, b); }
double combinedFriction(double a, double b) { return std::sqrt(a * b); }

void matchWarmStart(const std::vector<Contact>& contacts, std::vector<Contact>& fresh) {
  matchWarmStart(contacts, fresh, 0, fresh.size());
}

void matchWarmStart(const std::vector<Contact>& contacts, std::vector<Contact>& fresh, size_t first, size_t last) {
  if (first >= last) return;
  auto pairOf = [](const Contact& c) { return std::make_pair(c.a, c.b); };
  // the first previous contact not before fresh[first]'s pair, then both lists walked together
  size_t old = std::lower_bound(contacts.begin(), contacts.end(), pairOf(fresh[first]),
                                [&](const Contact& c, const std::pair<int, int>& p) { return pairOf(c) < p; }) -
               contacts.begin();
  for (size_t f = first; f < last; ++f) {
    Contact& c = fresh[f];
    while (old < contacts.size() && pairOf(contacts[old]) < pairOf(c)) ++old;
    if (old == contacts.size() || contacts[old].a != c.a || contacts[old].b != c.b) continue;
    const Contact& prev = contacts[old];
    for (int k = 0; k < c.manifold.count; ++k)
      for (int m = 0; m < prev.manifold.count; ++m)
        if (prev.manifold.points[m].id == c.manifold.points[k].id) {
          c.state[k].normalImpulse = prev.state[m].normalImpulse;
          c.state[k].tangentImpulse = prev.state[m].tangentImpulse;
        }
  }
}

}  // namespace sim::world

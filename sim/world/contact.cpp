#include "sim/world/contact.h"

#include <array>
#include <cmath>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

double combinedRestitution(double a, double b) { return std::max(a, b); }
double combinedFriction(double a, double b) { return std::sqrt(a * b); }

void matchWarmStart(const std::vector<Contact>& contacts, std::vector<Contact>& fresh) {
  size_t old = 0;
  for (Contact& c : fresh) {
    while (old < contacts.size() && std::make_pair(contacts[old].a, contacts[old].b) < std::make_pair(c.a, c.b)) ++old;
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

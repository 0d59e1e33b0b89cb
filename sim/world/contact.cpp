#include "sim/world/contact.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

void carryImpulses(const Contact& previous, Contact& c) {
  for (int k = 0; k < c.manifold.count; ++k)
    for (int m = 0; m < previous.manifold.count; ++m)
      if (previous.manifold.points[m].id == c.manifold.points[k].id) c.state[k] = previous.state[m];
}

}  // namespace sim::world

#include "sim/world/contact.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

CarriedPoints carriedPoints(const Contact& c) {
  return {c.manifold.count, {c.manifold.points[0].id, c.manifold.points[1].id}, {c.state[0], c.state[1]}};
}

void carryImpulses(const CarriedPoints& previous, Contact& c) {
  for (int k = 0; k < c.manifold.count; ++k)
    for (int m = 0; m < previous.count; ++m)
      if (previous.id[m] == c.manifold.points[k].id) c.state[k] = previous.state[m];
}

}  // namespace sim::world

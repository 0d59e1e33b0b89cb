// A test's world with its definition changed before it runs: a World's definition is fixed at its
// making (sim/world/world_def.h), so a test that varies one setting of a built scene makes the
// world again from the changed definition and the same bodies.
#pragma once

#include <utility>

namespace fixtures {

// `world` (not yet started) made again with its definition changed by `change(def)`
template <class World, class Change>
World redefined(const World& world, Change change) {
  auto def = world.def();
  change(def);
  return World(std::move(def), world.bodies);
}

}  // namespace fixtures

// A world's energy, alike in 2D and 3D: its bodies' kinetic energies (the notes' "Rigid body
// kinetic energy", each dimension's own) and the potential of its forces (gravity and springs).
#pragma once

namespace sim::core {

// `Energy` (kinetic, potential) of a world whose bodies' kinetic energies `kinetic(body)` gives
template <class Energy, class World, class Kinetic>
Energy worldEnergy(const World& world, Kinetic kinetic) {
  Energy e;
  for (const auto& b : world.bodies) e.kinetic += kinetic(b).total();
  e.potential = world.def().forces.potentialEnergy(world.bodies);
  return e;
}

}  // namespace sim::core

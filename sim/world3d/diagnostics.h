// Energies and momenta of the notes' "Rigid body kinetic energy" and "Forces and torques" slides,
// in 3D, and how far each q is from unit length.
#pragma once

#include "sim/world3d/world.h"

namespace sim::world3d {

struct KineticEnergy {
  double translational = 0.0;  // ½ m v·v
  double rotational = 0.0;     // ½ ω·L, L = I ω
  double total() const { return translational + rotational; }
};

struct Energy {
  double kinetic = 0.0;
  double potential = 0.0;  // gravity and springs
  double total() const { return kinetic + potential; }
};

KineticEnergy kineticEnergy(const Body& body);
Energy energy(const World& world);
// Σ m v
Vec3 linearMomentum(const World& world);
// about the world origin: Σ x × m v + I ω
Vec3 angularMomentum(const World& world);
// a hash of every body's pose and velocity bits (x, q, v, ω): equal hashes mean bit-identical runs
unsigned long long stateHash(const World& world);
// the largest | |q| − 1 | over the bodies
double quaternionDrift(const World& world);

}  // namespace sim::world3d

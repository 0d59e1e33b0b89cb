// Energies and momenta of the notes' "Rigid body kinetic energy" and "Forces and torques" slides.
#pragma once

#include "sim/core/body.h"
#include "sim/world/world.h"

namespace sim::world {

struct KineticEnergy {
  double translational = 0.0;  // ½ m v²
  double rotational = 0.0;     // ½ I ω²
  double total() const { return translational + rotational; }
};

struct Energy {
  double kinetic = 0.0;
  double potential = 0.0;  // gravity and springs
  double total() const { return kinetic + potential; }
};

// static bodies have infinite mass and no motion: they carry no energy or momentum
KineticEnergy kineticEnergy(const sim::core::Body& body);
Energy energy(const World& world);
// Σ m v
sim::core::Vec2 linearMomentum(const World& world);
// about the world origin: Σ x × m v + I ω
double angularMomentum(const World& world);
// a hash of every body's pose and velocity bits: equal hashes mean bit-identical runs
unsigned long long stateHash(const World& world);

}  // namespace sim::world

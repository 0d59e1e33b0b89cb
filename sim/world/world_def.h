// What a scene fixes for a run of the world, apart from the state the run changes (Box2D v3's
// b2WorldDef beside b2World, MuJoCo's mjModel beside mjData): the forces and timed impulses, the
// step grid and integrator, and the collision method asked for with its settings. A World holds
// its definition unchanged from its making; what `auto` resolves to is the world's state.
#pragma once

#include <vector>

#include "sim/core/collision_methods.h"
#include "sim/core/forces.h"
#include "sim/core/integrators.h"
#include "sim/core/settings.h"
#include "sim/world/contact.h"

namespace sim::world {

// an impulse j applied at exactly `time`: Δv = j/m, Δω = I⁻¹ (r′ × j)
struct ImpulseEvent {
  double time = 0.0;
  int body = 0;
  sim::core::Vec2 point = sim::core::Vec2::Zero();  // body coordinates, or world coordinates when pointInWorld
  bool pointInWorld = false;
  sim::core::Vec2 impulse = sim::core::Vec2::Zero();  // world coordinates
};

struct WorldDef {
  sim::core::ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  sim::core::Integrator integrator = sim::core::Integrator::SymplecticEuler;
  double dt = sim::core::settings::kDefaultDt;  // the step grid's spacing, s
  // the method asked for; `auto` is resolved when the run starts (World::collisions())
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;
  int velocityIterations = sim::core::settings::kVelocityIterations;
  int positionIterations = sim::core::settings::kPositionIterations;
  int substeps = sim::core::settings::kSubsteps;             // soft_step: substeps per step
  double contactHertz = sim::core::settings::kContactHertz;  // soft_step: contact stiffness, Hz (capped per substep)
  // soft_step: the widest SIMD a set's contacts are solved with, where the processor has it: 8
  // (AVX-512: eight doubles or sixteen floats at once), 4 (AVX2: four doubles, eight floats) or 1
  // (one at a time); the same state to the bit
  int simdWidth = 8;
  // soft_step: the numbers its contact solve is carried in (the world's state stays double)
  Precision precision = Precision::Double;
  // sequential and soft_step: islands at rest fall asleep and are not stepped until touched (sleep.h)
  bool sleep = false;
  // soft_step: threads that share each set of contacts (the same state with any number)
  int threads = 1;
  // soft_step: the contacts a step needs for each thread past the first before the threads share
  // it (0: settings.h's kContactsPerThread; the tests set 1, so that every thread works on their
  // small piles)
  int contactsPerThread = 0;
  // soft_step: a touching pair keeps its manifold, carried with the bodies, while it moved less than
  // this relative to the step it was made in, m (contact_recycle.h); 0: every pair collided every step
  double recycleDistance = 0.0;
};

}  // namespace sim::world

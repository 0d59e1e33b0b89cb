// What a 3D scene fixes for a run of the world, apart from the state the run changes (as the 2D
// world's definition, sim/world/world_def.h): the static planes, the forces and timed impulses,
// the step grid and integrator, and the collision method asked for with its settings.
#pragma once

#include <vector>

#include "sim/core/collision_methods.h"
#include "sim/core/settings.h"
#include "sim/world3d/contact3d.h"
#include "sim/world3d/forces.h"
#include "sim/world3d/integrators.h"

namespace sim::world3d {

// an impulse j applied at exactly `time`: Δv = j/m, Δω = I⁻¹ (r′ × j) with I = R I_b Rᵀ
struct ImpulseEvent {
  double time = 0.0;
  int body = 0;
  Vec3 point = Vec3::Zero();  // body coordinates, or world coordinates when pointInWorld
  bool pointInWorld = false;
  Vec3 impulse = Vec3::Zero();  // world coordinates, N·s
};

struct WorldDef {
  std::vector<Plane> planes;  // static half-spaces: floors and walls
  ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  // the splitting by default: the 3D method that keeps |q| = 1 and a free body's L (sim/README.md)
  Integrator integrator = Integrator::Splitting;
  // q ← q/|q| after every step; off, a four-vector method's |q| drifts as its closed form says
  bool normalizeQuaternions = true;
  double dt = sim::core::settings::kDefaultDt;  // the step grid's spacing, s (checked by World::start)
  // the method asked for; `auto` is resolved when the run starts (World::collisions())
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;
  int velocityIterations = sim::core::settings::kVelocityIterations;  // sequential
  int positionIterations = sim::core::settings::kPositionIterations;
};

}  // namespace sim::world3d

// The point forces of a scene (`forces:` of type force) acting on a body now, in world coordinates:
// what the teaching arrows show and the survey scales (notes: "Forces and torques").
#pragma once

#include <vector>

#include "sim/world/world.h"

namespace render::frame {

struct AppliedForce {
  sim::core::Vec2 point;  // world
  sim::core::Vec2 force;  // world
};

// the forces on `body` at the world's time: each on during [from, until), as the world applies them
std::vector<AppliedForce> pointForcesOn(const sim::world::World& world, int body);
// their torque about the body's center of mass: τ = Σ r′ × f
double torqueOf(const sim::core::Body& body, const std::vector<AppliedForce>& forces);

}  // namespace render::frame

// The forces a body's contacts put on it now, as the notes draw a free-body diagram: at each touching
// pair the normal force N n̂ and the friction force along the surface, from the impulses the stack
// solvers applied over the last step divided by it (sequential's accumulate over the step, soft_step's
// over a substep). The event and isolated methods apply impacts, not forces over a step: none there.
#pragma once

#include <vector>

#include "sim/world/world.h"

namespace render::frame {

struct ContactForce {
  sim::core::Vec2 point;     // where the pair's normal impulses are centred, m
  sim::core::Vec2 normal;    // the normal force on the body, N
  sim::core::Vec2 friction;  // the friction force on the body, N
};

// one per pair `body` touches, in the world's contact order
std::vector<ContactForce> contactForcesOn(const sim::world::World& world, int body);

}  // namespace render::frame

// The world described through DebugDraw: the bodies, the contacts and the impulses that a picture
// of the simulation shows (notes: "Rigid body state", "Impulses", "Collisions").
#pragma once

#include <vector>

#include "sim/debug_draw/debug_draw.h"
#include "sim/world/world.h"

namespace sim::describe {
// what is described goes through the simulator's drawing interface

// every body's shape in its current pose (and a radius for circles, so rotation shows)
void describeBodies(const sim::world::World& world, sim::debug_draw::DebugDraw& draw, double opacity = 1.0);

// a contact point as a picture shows it: where, and its normal from B into A (into B when A is
// static, as for a floor)
struct ContactMark {
  sim::core::Vec2 point, normal;
};
// the contacts touching now (world.contacts, and those the sleeping islands kept), a mark for each
// manifold point, appended to `out` in the order describeContactMarks draws them
void contactMarks(const sim::world::World& world, std::vector<ContactMark>& out);
// a dot at each mark and an arrow `normalLength` long along its normal
void describeContactMarks(const std::vector<ContactMark>& marks, double normalLength, sim::debug_draw::DebugDraw& draw);

// one impact of the collision response: the impulse on each moving body (γ n̂ on A, −γ n̂ on B,
// `impulseScale` m per N·s) from the point, the normal `normalLength` long and the point
void describeImpact(const sim::world::World& world, const sim::world::ImpactRecord& impact, double impulseScale,
                    double normalLength, sim::debug_draw::DebugDraw& draw);

// an event's impulse as an arrow that ends where it strikes the body, `impulseScale` m per N·s
struct Arrow {
  sim::core::Vec2 tail, head;
};
Arrow describeEventImpulse(const sim::world::World& world, const sim::world::ImpulseEvent& event, double impulseScale,
                           sim::debug_draw::DebugDraw& draw);

// every spring as a zigzag `amplitude` wide between its ends, and a dot at a world anchor
void describeSprings(const sim::world::World& world, double amplitude, sim::debug_draw::DebugDraw& draw);

}  // namespace sim::describe

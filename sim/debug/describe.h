// The world described through DebugDraw: the bodies, the contacts and the impulses that a picture
// of the simulation shows (notes: "Rigid body state", "Impulses", "Collisions").
#pragma once

#include "sim/debug_draw/debug_draw.h"
#include "sim/world/world.h"

namespace sim::debug {
// what is described goes through the simulator's drawing interface
using sim::core::Vec2;
using sim::debug_draw::DebugDraw;
using sim::debug_draw::DrawRole;
using sim::debug_draw::DrawStyle;
using sim::world::ImpactRecord;
using sim::world::ImpulseEvent;
using sim::world::World;

// every body's shape in its current pose (and a radius for circles, so rotation shows)
void describeBodies(const World& world, DebugDraw& draw, double opacity = 1.0);

// the contacts touching now (world.contacts, and those the sleeping islands kept): a dot at each
// manifold point and an arrow
// `normalLength` long along its normal, from B into A (into B when A is static, as for a floor)
void describeContacts(const World& world, double normalLength, DebugDraw& draw);

// one impact of the collision response: the impulse on each moving body (γ n̂ on A, −γ n̂ on B,
// `impulseScale` m per N·s) from the point, the normal `normalLength` long and the point
void describeImpact(const World& world, const ImpactRecord& impact, double impulseScale, double normalLength, DebugDraw& draw);

// an event's impulse as an arrow that ends where it strikes the body, `impulseScale` m per N·s
struct Arrow {
  Vec2 tail, head;
};
Arrow describeEventImpulse(const World& world, const ImpulseEvent& event, double impulseScale, DebugDraw& draw);

// every spring as a zigzag `amplitude` wide between its ends, and a dot at a world anchor
void describeSprings(const World& world, double amplitude, DebugDraw& draw);

}  // namespace sim::debug

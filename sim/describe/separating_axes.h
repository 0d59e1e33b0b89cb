// The notes' separating-axis test drawn (notes: "Collision detection (overlap) for polygons"): for
// every polygon pair close enough, the reference edge, the incident vertex and the separation
// written beside the edge; on request every other candidate edge labeled with its separation too.
#pragma once

#include "sim/debug_draw/debug_draw.h"
#include "sim/world/world.h"

namespace sim::describe {
// what is described goes through the simulator's drawing interface

// edge e's separation from the polygon `other`: min over its vertices v of n̂_e · (v − p_e), m
double edgeSeparation(const sim::core::Body& polygon, int edge, const sim::core::Body& other);

// every polygon pair (not both static) whose separation is at most `maxGap`: the reference edge,
// the incident vertex, and the separation written `labelOffset` inside the reference polygon from
// the edge; with `everyAxis`, every other candidate edge of both polygons labeled the same way
void describeSeparatingAxes(const sim::world::World& world, double maxGap, double labelOffset, sim::debug_draw::DebugDraw& draw,
                            bool everyAxis = false);

}  // namespace sim::describe

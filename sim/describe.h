// The world described through DebugDraw: what a frame of the simulation shows.
#pragma once

#include "debug_draw.h"
#include "world.h"

namespace sim {

// every body's shape in its current pose (and a radius for circles, so rotation shows)
void describeBodies(const World& world, DebugDraw& draw, double opacity = 1.0);

}  // namespace sim

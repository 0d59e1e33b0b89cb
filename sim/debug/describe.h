// The world described through DebugDraw: what a frame of the simulation shows.
#pragma once

#include "sim/debug/debug_draw.h"
#include "sim/world/world.h"

namespace sim::debug {
using namespace sim::core;
using namespace sim::world;

// every body's shape in its current pose (and a radius for circles, so rotation shows)
void describeBodies(const World& world, DebugDraw& draw, double opacity = 1.0);

}  // namespace sim::debug

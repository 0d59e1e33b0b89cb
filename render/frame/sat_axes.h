// `sat_axes: true`: the separating-axis test's every candidate (notes: "Collision detection", SAT):
// each edge of both polygons is an axis, and its separation, min over the other polygon's vertices
// of the distance past the edge, is written beside it; the largest is the reference edge.
#pragma once

#include "sim/debug/debug_draw.h"
#include "sim/world/world.h"

namespace render::frame {

// edge e's separation from the polygon `other`: min over its vertices v of n̂_e · (v − p_e), m
double edgeSeparation(const sim::core::Body& polygon, int edge, const sim::core::Body& other);

// every edge of polygons `a` and `b` labeled with its separation, `labelOffset` inside its polygon,
// except edge `skipEdge` of `a` (the reference edge, labeled already)
void describeCandidateAxes(const sim::world::World& world, int a, int b, int skipEdge, double labelOffset, sim::debug::DebugDraw& draw);

}  // namespace render::frame

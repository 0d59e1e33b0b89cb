// The broad phase: which pairs of bodies can touch at all, from their bounding boxes, so that
// bodies far apart cost nothing (a hashed uniform grid, Ericson 7.1; sort and sweep, 7.5.2, for few
// bodies or many large ones).
#pragma once

#include <utility>
#include <vector>

#include "sim/collision/collide.h"

namespace sim::collision {

// pairs (i, j), i < j, whose boxes overlap, sorted; pairs of two boxes marked `fixed` (static
// bodies) are skipped. Unbounded boxes (planes) pair with everything their bounds reach.
std::vector<std::pair<int, int>> overlappingPairs(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed);

}  // namespace sim::collision

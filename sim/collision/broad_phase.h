// The broad phase: which pairs of bodies can touch at all, from their bounding boxes, so that
// bodies far apart cost nothing (sort and sweep, Ericson 7.5.2).
#pragma once

#include <utility>
#include <vector>

#include "sim/collision/collide.h"

namespace sim::collision {
using namespace sim::core;

// pairs (i, j), i < j, whose boxes overlap, sorted; pairs of two boxes marked `fixed` (static
// bodies) are skipped. Unbounded boxes (planes) pair with everything their bounds reach.
std::vector<std::pair<int, int>> overlappingPairs(const std::vector<Aabb>& boxes, const std::vector<bool>& fixed);

}  // namespace sim::collision

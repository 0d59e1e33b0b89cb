// The outline of a body made of parts, drawn as one body: each part's boundary less what lies
// inside (or along) another part, so that no seam shows where two parts touch.
#pragma once

#include <vector>

#include "sim/core/shape.h"

namespace sim::describe {

struct OutlineSegment {
  sim::core::Vec2 a, b;
};

// the outline of compound `shape` in its body's coordinates (a circle part as a polygon of
// `circleSegments` chords), a piece per maximal run of a part's edge on the outside
std::vector<OutlineSegment> partOutline(const sim::core::Shape& shape, int circleSegments = 96);

}  // namespace sim::describe

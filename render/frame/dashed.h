// A line drawn dashed, as segments: another simulator's bodies (--overlay) and an impulse still to
// come (a poll's question frame), told apart from what is drawn solid.
#pragma once

#include <vector>

#include "render/draw/canvas.h"

namespace render::frame {

// the polyline through `points` (closed back to the first when `closed`) as dashes `dash` long with
// `gap` between them, in world units, the pattern going on around the corners
void dashedLine(const std::vector<sim::core::Vec2>& points, bool closed, double dash, double gap, const render::draw::Pen& pen,
                render::draw::Canvas& draw);

}  // namespace render::frame

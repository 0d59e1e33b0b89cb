// A 3D frame's draw list as a golden record keeps it (draw_list_json.h): each solid a call of kind
// "solid" (its mesh the text, its numbers the position x then R by rows), then the overlay's calls
// in pixels; the view is the frame's size in pixels, so a draw-list tolerance of 1e-6 is a
// millionth of the frame's larger side.
#pragma once

#include "render/draw/style.h"
#include "render/draw3d/canvas3d.h"
#include "render/golden/draw_list_json.h"

namespace render::golden {

DrawnFrame drawnFrame3d(const render::draw3d::DrawList3d& list, const render::draw::Style& style, int widthPx, int heightPx);

}  // namespace render::golden

// Another simulator's trajectory over ours (`render`/`snapshot --overlay`): each of its bodies
// outlined, dashed, in the overlay colour at its pose at the frame's time, and a legend naming both
// runs. Drawn over our bodies and under the texts, past the label placer: the frame is otherwise
// the frame without it.
#pragma once

#include "render/draw/camera.h"
#include "render/draw/canvas.h"
#include "render/frame/caption.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

// the outlines of the bodies of `overlay` at the world's time, and the legend below the clock
void drawTraceOverlay(const render::scene::Scene& def, const render::scene::TraceOverlayDef& overlay,
                      const sim::world::World& world, const render::draw::Camera& camera, render::draw::Canvas& draw);

}  // namespace render::frame

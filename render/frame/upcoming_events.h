// A poll's question frame shows what is still to come: each event whose time lies ahead, as a dashed
// impulse arrow ending where it will strike, labelled with its time ("j at t = 0.5 s"). So variants
// that differ only in a future event (struck at the center or at the end) look different at t = 0,
// and the question can be asked from the picture.
#pragma once

#include "render/draw/camera.h"
#include "render/draw/canvas.h"
#include "sim/world/world.h"

namespace render::frame {

// every event of `world` after its present time, as a dashed arrow `impulseScale` m per N·s ending at
// its point (the head solid), `lineWidthPx` wide dashes, labelled beyond its tail
void drawUpcomingEvents(const sim::world::World& world, double impulseScale, const render::draw::Camera& camera,
                        double lineWidthPx, render::draw::Canvas& draw);

// "j at t = 0.5 s"
std::string upcomingText(double t);

}  // namespace render::frame

// The style of a scene's frames: each role's color as the render: block sets it, each body's own
// color or the palette's next, the line width and the text size.
#pragma once

#include "render/draw/style.h"
#include "render/scene/scene.h"

namespace render::scene {

// the text size for frames `frameHeight` pixels high: the render: block's, or the height / 36 (20 px
// at 720p: readable on a projector, small enough not to cover the bodies), at least 11 px
int fontSizeFor(const RenderDef& render, int frameHeight);
// the line width for such frames, px: the render: block's, or the height / 360 (3 px at 1080p, 2 at 720p)
double lineWidthFor(const RenderDef& render, int frameHeight);

// the scene's style for frames `frameHeight` pixels high: each body its own color, or the palette's
// next one (static bodies the static color), the render: block's colors, line width and font size
draw::Style makeStyle(const Scene& scene, int frameHeight);
// the same from the block itself (2D or 3D): `staticBodies` by body index (gray unless colored),
// each teaching arrow's own color ("" for its role's)
draw::Style makeStyle(const RenderDef& render, const std::vector<bool>& staticBodies, const std::vector<std::string>& arrowColors,
                      int frameHeight);

}  // namespace render::scene

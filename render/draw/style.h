// What each drawing role looks like in one scene: colors from the bodies' own `color` and the
// render: block, line width and text size in output pixels. The canvas turns a DrawStyle (role,
// body, opacity) into GL colors and sizes through this.
#pragma once

#include <vector>

#include "render/draw/color.h"
#include "sim/debug/debug_draw.h"
#include "sim/scene/scene_def.h"

namespace render::draw {

struct Style {
  Color background{1.0, 1.0, 1.0, 1.0};
  std::vector<Color> bodies;  // by body index
  Color staticBody, contact, normal, impulse, velocity, trail, referenceEdge, incidentVertex, spring, text;
  // the lecture overlays; `arrows` by index of render.overlays.arrows, the arrow's own color or none (alpha 0)
  Color offset, omega, frame, path, force, torque, momentum, potential, total, panel;
  std::vector<Color> arrows;
  double lineWidth = 2.0;  // output pixels
  int fontSize = 20;       // output pixels per em

  // a body's base color; `trail` for -1 or an index past the end
  Color body(int index) const { return index >= 0 && index < static_cast<int>(bodies.size()) ? bodies[index] : trail; }
};

// the text size for frames `frameHeight` pixels high: the render: block's, or the height / 36 (20 px
// at 720p: readable on a projector, small enough not to cover the bodies), at least 11 px
int fontSizeFor(const sim::scene::RenderDef& render, int frameHeight);

// the scene's style for frames `frameHeight` pixels high: each body its own color, or the palette's
// next one (static bodies the static color), the render: block's colors, line width and font size
Style makeStyle(const sim::scene::SceneDef& scene, int frameHeight);

}  // namespace render::draw

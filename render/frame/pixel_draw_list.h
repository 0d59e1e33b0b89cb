// An image's draw list in its own pixels (x right, y down), each text with the box it was drawn in:
// what `snapshot --draw-list` writes beside each PNG, so that a test (ours, or a course's) can hold
// the layout to what a slide promises: no two texts overlap, no panel covers a body.
//
//   {"width": 1920, "height": 1080,
//    "calls": [{"kind": "polygon", "pen": "Body#0", "color": "#3b6ea5", "numbers": [x0, y0, x1, y1, ...]},
//              {"kind": "text", "pen": "Caption", "color": "#1f1f1f", "numbers": [x, y], "text": "t = 0.500 s",
//               "box": [x0, y0, x1, y1]}, ...]}
//
// The calls are the golden draw lists' (render/golden/draw_list_json.h: `kind`, `pen`, `color`,
// `numbers`, `text`) with every point in pixels and a circle's radius in pixels; a half-plane's
// numbers are a point on its edge and its outward normal, y down. A sheet of panels holds every
// cell's calls moved to the cell, then its titles and caption.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/draw_list.h"
#include "render/draw/style.h"
#include "render/draw/text.h"
#include "render/frame/caption.h"
#include "render/frame/label_place.h"

namespace render::frame {

struct PixelCall {
  std::string kind, pen, color, text;
  std::vector<double> numbers;  // px
  std::optional<PixelBox> box;  // a text's, as drawn
  render::draw::Pen style;      // the call's pen (for tests; the JSON has its name)
};

struct PixelDrawList {
  int width = 0, height = 0;
  std::vector<PixelCall> calls;
};

// the box a text of `width` px and a line `lineHeight` px high is drawn in with its point at `at`
// (TextRenderer::draw: the corner rounded to whole pixels)
PixelBox textBox(const sim::core::Vec2& at, render::draw::Anchor anchor, int width, int lineHeight);

// a frame's calls through `camera` in its pixels, each text measured by `width` at `fontPx` (a
// label centered on its point, a caption with its top-left corner there, as GlCanvas draws them)
PixelDrawList pixelDrawList(const render::draw::DrawList& list, const render::draw::Style& style,
                            const render::draw::Camera& camera, const TextWidth& width, int fontPx);
// `cell`'s calls moved by (dx, dy) px, added to `sheet`
void addMoved(PixelDrawList& sheet, const PixelDrawList& cell, double dx, double dy);
// a text drawn straight into an image (a sheet's title or caption), in `color`
void addText(PixelDrawList& image, const std::string& text, const sim::core::Vec2& at, render::draw::Anchor anchor, int width,
             int lineHeight, const render::draw::Color& color);

void writePixelDrawList(std::ostream& out, const PixelDrawList& list);
// the draw list's file beside an image: "a/b-t0.5.png" → "a/b-t0.5.json"
std::string drawListPathFor(const std::string& pngPath);

}  // namespace render::frame

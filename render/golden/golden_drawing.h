// What a golden run draws with, 2D or 3D: a GL context only when pixels are asked, and text
// measured alike with and without one, so that labels are placed by the same widths either way.
#pragma once

#include <memory>

#include "render/draw/gl_context.h"
#include "render/draw/text.h"
#include "render/golden/golden_def.h"
#include "render/golden/golden_run.h"

namespace render::golden {

class GoldenDrawing {
 public:
  // at the golden size; with `pixels`, the GL context loaded and its renderer and version named in
  // `run` (throws std::runtime_error when GL cannot be loaded)
  GoldenDrawing(const GoldenDef& golden, bool pixels, GoldenRun& run);

  render::draw::GlContext* gl() const { return gl_.get(); }  // null without pixels
  render::draw::TextRenderer* text() { return &text_; }

 private:
  std::unique_ptr<render::draw::GlContext> gl_;
  render::draw::TextRenderer text_;
};

}  // namespace render::golden

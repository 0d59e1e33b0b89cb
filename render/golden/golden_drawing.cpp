#include "render/golden/golden_drawing.h"

namespace render::golden {

GoldenDrawing::GoldenDrawing(const GoldenDef& golden, bool pixels, GoldenRun& run) {
  if (!pixels) return;
  gl_ = std::make_unique<render::draw::GlContext>(golden.width, golden.height);
  run.renderer = gl_->renderer();
  run.rendererVersion = gl_->version();
}

}  // namespace render::golden

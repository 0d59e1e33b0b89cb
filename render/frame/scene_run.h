// One run of a scene through the renderer: its world stepped forward to each time asked for (split
// exactly there, whatever the physics step), its history gathered on the way, and the frame at that
// time painted with GL.
#pragma once

#include <memory>

#include "render/draw/gl_canvas.h"
#include "render/draw/style.h"
#include "render/frame/frame_painter.h"
#include "render/frame/history.h"
#include "sim/world/world.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

class SceneRun {
 public:
  // `def` must outlive the run; the GL context is the frame's size and current on this thread
  // (without one, only draw lists can be made)
  SceneRun(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey, GlContext* gl = nullptr,
           TextRenderer* text = nullptr);

  // the frame at exactly time t, which must not be earlier than the last one; with `strobe` > 0,
  // that many earlier poses at t·i/strobe (i = 0 … strobe − 1) drawn fading behind the present one,
  // which needs a fresh run (nothing drawn yet). Throws sim::world::Diverged.
  Image frameAt(double t, int strobe = 0);
  // the draw calls of the frame at time t, without GL (the draw-list level of the tests); `placed`
  // (when given) is told where each text went (its box in pixels, the anchor it names)
  DrawList drawListAt(double t, int strobe = 0, std::vector<PlacedText>* placed = nullptr);
  // the title card alone (title_card.h), the frame's size; needs the text renderer
  Image titleCard();
  // video frames say when they are slowed (empty: never), see FramePainter
  void showSlowMotion(FramePainter::SlowFactor factorAt) { painter_.showSlowMotion(std::move(factorAt)); }

  const sim::world::World& world() const { return world_; }

 private:
  std::vector<DrawList> advance(double t, int strobe);

  const render::scene::Scene& def_;
  Camera camera_;
  Style style_;
  FramePainter painter_;
  sim::world::World world_;
  History history_;
  std::unique_ptr<GlCanvas> canvas_;
  TextRenderer* text_;
};

}  // namespace render::frame

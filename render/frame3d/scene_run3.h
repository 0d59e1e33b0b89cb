// One run of a 3D scene through the renderer, as SceneRun is for 2D: its world stepped forward to
// each time asked for (split exactly there), its history gathered on the way, the frame at that
// time painted in perspective with GL, or recorded as a draw list.
#pragma once

#include <memory>

#include "render/draw3d/gl_canvas3.h"
#include "render/frame/frame_source.h"
#include "render/frame3d/frame_painter3.h"

namespace render::frame3d {

class SceneRun3 final : public render::frame::FrameSource {
 public:
  // `def` must outlive the run; the GL context is the frame's size and current on this thread
  // (without one, only draw lists can be made)
  SceneRun3(const render::scene3d::Scene& def, const Camera3& camera, const RunSurvey3& survey,
            render::draw::GlContext* gl = nullptr, render::draw::TextRenderer* text = nullptr);

  // the frame at exactly time t, not earlier than the last one. Throws sim::world3d::Diverged.
  render::draw::Image frameAt(double t) override;
  // the same into `frame`, its storage reused when it has the frame's size (a video's few buffers)
  void frameAt(double t, render::draw::Image& frame) override;
  render::draw::Image titleCard() override;
  render::draw::Image answerCard() override;
  void showSlowMotion(std::function<double(double)> factorAt) override { painter_.showSlowMotion(std::move(factorAt)); }
  // the calls of the frame at time t, without GL (the draw-list level of the tests)
  DrawList3 drawListAt(double t);

  const sim::world3d::World& world() const { return world_; }

 private:
  const render::scene3d::Scene& def_;
  Camera3 camera_;
  render::draw::Style style_;
  FramePainter3 painter_;
  sim::world3d::World world_;
  History3 history_;
  std::unique_ptr<GlCanvas3> canvas_;
  render::draw::TextRenderer* text_;
};

}  // namespace render::frame3d

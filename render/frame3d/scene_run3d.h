// One run of a 3D scene through the renderer, as SceneRun is for 2D: its world stepped on the
// scene's own step grid (never split at a frame's time: a time between two steps is drawn from a
// copy advanced to it), its history gathered on the way, the frame at that time painted in
// perspective with GL, or recorded as a draw list.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "render/draw3d/gl_canvas3d.h"
#include "render/frame/frame_source.h"
#include "render/frame/stepped_run.h"
#include "render/frame3d/frame_painter3d.h"

namespace render::frame3d {

class SceneRun3d final : public render::frame::FrameSource {
 public:
  // `def` must outlive the run; the GL context is the frame's size and current on this thread
  // (without one, only draw lists can be made)
  SceneRun3d(const render::scene3d::Scene& def, const render::draw3d::Camera3d& camera, const RunSurvey3d& survey,
             render::draw::GlContext* gl = nullptr, render::draw::TextRenderer* text = nullptr);

  // where the run ends, its last step cut there: the scene's duration unless set before the first frame
  void endAt(double end) { run_.endAt(end); }
  // `observer` (e.g. a trace) is told of every step and event of the run itself, never of the
  // copies drawn between steps; set it before the first frame
  void follow(sim::world3d::StepObserver* observer) { run_.follow(observer); }
  // the run taken on to its end (what a trace needs after the last picture), the pictures along it
  // not yet taken taken on the way. Throws as frameAt.
  void finish();
  // a picture taken as the run passes instant t: exactly what a fresh run's frameAt(t) paints,
  // without a video's slow-motion note (a video's poster from the video's own run, as SceneRun's).
  // Set before the first frame; `shot` is told it by the first picture asked at t′ ≥ t (frameAt,
  // drawListAt), by takePicturesAlong(), or by finish().
  void pictureAlong(double t, std::function<void(render::draw::Image)> shot);
  // the pictures along the run not yet taken, taken: the run stepped only as far as they need
  void takePicturesAlong() { takeAlong(run_.end()); }

  // the frame at time t, not earlier than the last one. Throws sim::core::Diverged.
  render::draw::Image frameAt(double t) override;
  // the same into `frame`, its storage reused when it has the frame's size (a video's few buffers)
  void frameAt(double t, render::draw::Image& frame) override;
  render::draw::Image titleCard() override;
  render::draw::Image answerCard() override;
  void showSlowMotion(std::function<double(double)> factorAt) override { painter_.showSlowMotion(std::move(factorAt)); }
  // the calls of the frame at time t, without GL (the draw-list level of the tests)
  render::draw3d::DrawList3d drawListAt(double t);

  // the world the last picture was drawn from: the run's own, or its copy between two steps
  const sim::world3d::World& world() const { return run_.world(); }
  // the run's own world, at its last step
  const sim::world3d::World& runWorld() const { return run_.runWorld(); }
  // the steps this run took for its pictures: none where the survey kept the run at their instants
  long stepsTaken() const { return run_.stepsTaken(); }

 private:
  using Run = SpatialRun;
  using State = Run::State;
  // the state at t painted into `frame`
  void paint(const State& state, render::draw::Image& frame);
  // the pictures along the run whose times are at most `upTo`, taken
  void takeAlong(double upTo);
  struct Along {
    double time;
    std::function<void(render::draw::Image)> shot;
  };

  const render::scene3d::Scene& def_;
  render::draw3d::Camera3d camera_;
  render::draw::Style style_;
  FramePainter3d painter_;
  Run run_;
  std::vector<Along> along_;  // the pictures along the run not yet taken, in the order asked
  std::unique_ptr<render::draw3d::GlCanvas3d> canvas_;
  render::draw::TextRenderer* text_;
};

}  // namespace render::frame3d

#include "render/frame3d/scene_run3d.h"

#include <algorithm>
#include <stdexcept>

#include "render/frame/title_card.h"
#include "sim/scene3d/scene_build.h"

namespace render::frame3d {
using namespace render::draw3d;

namespace {

// the width of text as drawn, or none (the painter then estimates it)
render::frame::TextWidth textWidth(render::draw::TextRenderer* text, int sizePx) {
  if (!text) return {};
  return [text, sizePx](const std::string& s) { return text->measure(s, sizePx).width; };
}

}  // namespace

SceneRun3d::SceneRun3d(const render::scene3d::Scene& def, const Camera3d& camera, const RunSurvey3d& survey,
                       render::draw::GlContext* gl, render::draw::TextRenderer* text)
    : def_(def),
      camera_(camera),
      style_(render::scene3d::makeStyle(def, camera.heightPx())),
      painter_(def, camera, survey, textWidth(text, style_.fontSize)),
      run_(
          [&] {
            sim::world3d::World world = sim::scene3d::buildWorld(def.model);
            History3d history(world, painter_.historyOptions());
            return State{std::move(world), std::move(history)};
          }(),
          def.model.duration),
      text_(text) {
  if (gl && text) canvas_ = std::make_unique<GlCanvas3d>(*gl, *text, style_);
  // the survey's run kept at the pictures' instants: the drawing goes on from there, its paths
  // respaced to this camera's pixels
  const History3d::Options o = painter_.historyOptions();
  const auto sameRecord = [&o](const History3d::Options& kept) {
    return kept.trails == o.trails && kept.points == o.points && kept.omegaTips == o.omegaTips;
  };
  // the lambda holds the kept run, so its states outlive the run that reads them
  if (const std::shared_ptr<const KeptRun3d>& kept = survey.kept; kept && sameRecord(kept->options))
    run_.resumeFrom(&kept->states, kept->end, [kept, o](State& s) { s.history.respace(o.spacing, o.omegaSpacing); });
}

void SceneRun3d::pictureAlong(double t, std::function<void(render::draw::Image)> shot) {
  if (!canvas_) throw std::logic_error("SceneRun3d::pictureAlong needs a GL context");
  if (!run_.fresh()) throw std::logic_error("pictures along a run are asked before its first frame");
  along_.push_back({t, std::move(shot)});
}

void SceneRun3d::takeAlong(double upTo) {
  // the earliest first: the run only goes forward
  for (;;) {
    auto a = std::min_element(along_.begin(), along_.end(), [](const Along& x, const Along& y) { return x.time < y.time; });
    if (a == along_.end() || a->time > upTo) return;
    const Along picked = std::move(*a);
    along_.erase(a);
    // a still, as a fresh run's frameAt paints it: without the video's slow-motion note
    std::function<double(double)> slow = painter_.slowMotion();
    painter_.showSlowMotion({});
    render::draw::Image picture;
    paint(run_.reach(picked.time), picture);
    painter_.showSlowMotion(std::move(slow));
    picked.shot(std::move(picture));
  }
}

void SceneRun3d::finish() {
  takeAlong(run_.end());
  run_.finish();
}

render::draw::Image SceneRun3d::frameAt(double t) {
  render::draw::Image frame;
  frameAt(t, frame);
  return frame;
}

void SceneRun3d::frameAt(double t, render::draw::Image& frame) {
  if (!canvas_) throw std::logic_error("SceneRun3d::frameAt needs a GL context");
  takeAlong(t);
  paint(run_.reach(t), frame);
}

void SceneRun3d::paint(const State& state, render::draw::Image& frame) {
  canvas_->begin(camera_);
  painter_.paint(state.world, state.history, *canvas_);
  canvas_->finish(frame);
}

render::draw::Image SceneRun3d::titleCard() {
  if (!text_) throw std::logic_error("SceneRun3d::titleCard needs a text renderer");
  return render::frame::composeSceneCard(def_.render, def_.model.name, def_.model.description, false, camera_.widthPx(),
                                         camera_.heightPx(), style_, *text_);
}

render::draw::Image SceneRun3d::answerCard() {
  if (!text_) throw std::logic_error("SceneRun3d::answerCard needs a text renderer");
  return render::frame::composeSceneCard(def_.render, def_.model.name, def_.model.description, true, camera_.widthPx(),
                                         camera_.heightPx(), style_, *text_);
}

DrawList3d SceneRun3d::drawListAt(double t) {
  takeAlong(t);
  const State& state = run_.reach(t);
  DrawList3d list;
  painter_.paint(state.world, state.history, list);
  return list;
}

}  // namespace render::frame3d

#include "render/frame3d/scene_run3.h"

#include <stdexcept>

#include "render/frame/title_card.h"
#include "sim/scene3d/scene_build.h"

namespace render::frame3d {

namespace {

// the width of text as drawn, or none (the painter then estimates it)
render::frame::TextWidth textWidth(render::draw::TextRenderer* text, int sizePx) {
  if (!text) return {};
  return [text, sizePx](const std::string& s) { return text->measure(s, sizePx).width; };
}

}  // namespace

SceneRun3::SceneRun3(const render::scene3d::Scene& def, const Camera3& camera, const RunSurvey3& survey,
                     render::draw::GlContext* gl, render::draw::TextRenderer* text)
    : def_(def),
      camera_(camera),
      style_(render::scene3d::makeStyle(def, camera.heightPx())),
      painter_(def, camera, survey, textWidth(text, style_.fontSize)),
      world_(sim::scene3d::buildWorld(def.model)),
      history_(world_, painter_.historyOptions()),
      text_(text) {
  if (gl && text) canvas_ = std::make_unique<GlCanvas3>(*gl, *text, style_);
}

render::draw::Image SceneRun3::frameAt(double t) {
  render::draw::Image frame;
  frameAt(t, frame);
  return frame;
}

void SceneRun3::frameAt(double t, render::draw::Image& frame) {
  if (!canvas_) throw std::logic_error("SceneRun3::frameAt needs a GL context");
  world_.advanceTo(t, &history_);
  canvas_->begin(camera_);
  painter_.paint(world_, history_, *canvas_);
  canvas_->finish(frame);
}

render::draw::Image SceneRun3::titleCard() {
  if (!text_) throw std::logic_error("SceneRun3::titleCard needs a text renderer");
  return render::frame::composeSceneCard(def_.render, def_.model.name, def_.model.description, false, camera_.widthPx(),
                                         camera_.heightPx(), style_, *text_);
}

render::draw::Image SceneRun3::answerCard() {
  if (!text_) throw std::logic_error("SceneRun3::answerCard needs a text renderer");
  return render::frame::composeSceneCard(def_.render, def_.model.name, def_.model.description, true, camera_.widthPx(),
                                         camera_.heightPx(), style_, *text_);
}

DrawList3 SceneRun3::drawListAt(double t) {
  world_.advanceTo(t, &history_);
  DrawList3 list;
  painter_.paint(world_, history_, list);
  return list;
}

}  // namespace render::frame3d

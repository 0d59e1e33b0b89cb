#include "render/frame/scene_run.h"

#include <stdexcept>

#include "render/frame/title_card.h"
#include "render/scene/scene_style.h"
#include "sim/debug/describe.h"
#include "sim/scene/scene_build.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

namespace {

// how faint the oldest strobe ghost is, and the newest (a ghost never competes with the present)
constexpr double kOldestGhost = 0.15;
constexpr double kNewestGhost = 0.55;

// the width of text as drawn, or none (FramePainter then estimates it)
TextWidth textWidth(TextRenderer* text, int sizePx) {
  if (!text) return {};
  return [text, sizePx](const std::string& s) { return text->measure(s, sizePx).width; };
}

}  // namespace

SceneRun::SceneRun(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey, GlContext* gl,
                   TextRenderer* text)
    : def_(def),
      camera_(camera),
      style_(makeStyle(def, camera.heightPx())),
      painter_(def, camera, survey, textWidth(text, style_.fontSize)),
      world_(sim::scene::buildWorld(def.model)),
      history_(world_, painter_.historyOptions()),
      text_(text) {
  if (gl && text) canvas_ = std::make_unique<GlCanvas>(*gl, *text, style_);
}

std::vector<DrawList> SceneRun::advance(double t, int strobe) {
  std::vector<DrawList> ghosts;
  if (strobe > 0 && world_.time > 0.0) throw std::logic_error("a strobe image needs a fresh run");
  for (int i = 0; i < strobe; ++i) {
    world_.advanceTo(t * i / strobe, &history_);
    DrawList ghost;
    const double opacity = kOldestGhost + (kNewestGhost - kOldestGhost) * i / std::max(1, strobe - 1);
    PhysicsDraw physics(ghost);
    sim::debug::describeBodies(world_, physics, opacity);
    // ghosts of moving bodies only: a static body's ghost would only darken it
    ghosts.emplace_back();
    RoleFilter moving(ghosts.back(), [](Role r) { return r != Role::StaticBody; });
    ghost.replay(moving);
  }
  world_.advanceTo(t, &history_);
  return ghosts;
}

Image SceneRun::frameAt(double t, int strobe) {
  if (!canvas_) throw std::logic_error("SceneRun::frameAt needs a GL context");
  const std::vector<DrawList> ghosts = advance(t, strobe);
  canvas_->begin(camera_);
  painter_.paint(world_, history_, ghosts, *canvas_);
  return canvas_->finish();
}

Image SceneRun::titleCard() {
  if (!text_) throw std::logic_error("SceneRun::titleCard needs a text renderer");
  return composeTitleCard(camera_.widthPx(), camera_.heightPx(), titleOf(def_), def_.model.description, style_, *text_);
}

DrawList SceneRun::drawListAt(double t, int strobe, std::vector<PlacedText>* placed) {
  const std::vector<DrawList> ghosts = advance(t, strobe);
  DrawList list;
  painter_.paint(world_, history_, ghosts, list, placed);
  return list;
}

}  // namespace render::frame

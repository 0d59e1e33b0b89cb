#include "render/frame/scene_run.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/frame/title_card.h"
#include "render/scene/scene_style.h"
#include "sim/describe/describe.h"
#include "sim/core/settings.h"
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

SceneRun::State SceneRun::startState(const sim::scene::SceneDef& model, History::Options options) {
  sim::world::World world = sim::scene::buildWorld(model);
  History history(world, std::move(options));
  return {std::move(world), std::move(history)};
}

SceneRun::SceneRun(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey, GlContext* gl,
                   TextRenderer* text)
    : def_(def),
      camera_(camera),
      style_(makeStyle(def, camera.heightPx())),
      painter_(def, camera, survey, textWidth(text, style_.fontSize)),
      run_(startState(def.model, painter_.historyOptions()), def.model.duration),
      text_(text) {
  if (gl && text) canvas_ = std::make_unique<GlCanvas>(*gl, *text, style_);
  // the survey's run kept at the pictures' instants: the drawing goes on from there
  goOnFrom(run_, survey.kept, painter_.historyOptions());
}

void SceneRun::finish() {
  takeAlong(run_.end());
  run_.finish();
}

DrawList SceneRun::ghostOf(const State& state, int i, int strobe) {
  DrawList ghost;
  const double opacity = kOldestGhost + (kNewestGhost - kOldestGhost) * i / std::max(1, strobe - 1);
  PhysicsDraw physics(ghost);
  sim::describe::describeBodies(state.world, physics, opacity);
  // ghosts of moving bodies only: a static body's ghost would only darken it
  DrawList moving;
  RoleFilter filter(moving, [](Role r) { return r != Role::StaticBody; });
  ghost.replay(filter);
  return moving;
}

std::vector<SceneRun::Need> SceneRun::needsOf(const std::vector<double>& instants, int strobe) {
  std::vector<Need> needs;
  for (size_t k = 0; k < instants.size(); ++k) {
    for (int i = 0; i < strobe; ++i) needs.push_back({instants[k] * i / strobe, k, i});
    needs.push_back({instants[k], k, -1});
  }
  std::stable_sort(needs.begin(), needs.end(), [](const Need& a, const Need& b) {
    return a.time < b.time || (a.time == b.time && a.ghost >= 0 && b.ghost < 0);
  });
  return needs;
}

void SceneRun::picturesAt(const std::vector<double>& instants, int strobe,
                          const std::function<void(size_t, const State&, const std::vector<DrawList>&)>& picture) {
  if (strobe > 0 && run_.runWorld().time > 0.0) throw std::logic_error("a strobe image needs a fresh run");
  std::vector<std::vector<DrawList>> ghosts(instants.size(), std::vector<DrawList>(strobe));
  for (const Need& n : needsOf(instants, strobe)) {
    takeAlong(n.time);
    const State& state = run_.reach(n.time);
    if (n.ghost >= 0) {
      ghosts[n.instant][n.ghost] = ghostOf(state, n.ghost, strobe);
      continue;
    }
    picture(n.instant, state, ghosts[n.instant]);
    ghosts[n.instant].clear();
  }
}

void SceneRun::pictureAlong(double t, int strobe, std::function<void(Image)> shot) {
  if (!canvas_) throw std::logic_error("SceneRun::pictureAlong needs a GL context");
  if (!run_.fresh()) throw std::logic_error("pictures along a run are asked before its first frame");
  along_.push_back({needsOf({t}, strobe), 0, strobe, std::vector<DrawList>(strobe), std::move(shot)});
}

void SceneRun::takeAlong(double upTo) {
  // the earliest need of all the pictures first: the run only goes forward
  for (;;) {
    Along* a = nullptr;
    for (Along& b : along_)
      if (b.next < b.needs.size() && b.needs[b.next].time <= upTo && (!a || b.needs[b.next].time < a->needs[a->next].time))
        a = &b;
    if (!a) return;
    const Need& n = a->needs[a->next++];
    const State& state = run_.reach(n.time);
    if (n.ghost >= 0) {
      a->ghosts[n.ghost] = ghostOf(state, n.ghost, a->strobe);
      continue;
    }
    // a still, as a fresh run's frameAt paints it: without the video's slow-motion note
    FramePainter::SlowFactor slow = painter_.slowMotion();
    painter_.showSlowMotion({});
    Image picture;
    paint(state, a->ghosts, picture);
    painter_.showSlowMotion(std::move(slow));
    a->ghosts.clear();
    a->shot(std::move(picture));
  }
}

Image SceneRun::frameAt(double t, int strobe) {
  if (!canvas_) throw std::logic_error("SceneRun::frameAt needs a GL context");
  Image frame;
  picturesAt({t}, strobe, [&](size_t, const State& state, const std::vector<DrawList>& ghosts) { paint(state, ghosts, frame); });
  return frame;
}

void SceneRun::frameAt(double t, Image& frame) {
  if (!canvas_) throw std::logic_error("SceneRun::frameAt needs a GL context");
  takeAlong(t);
  paint(run_.reach(t), {}, frame);
}

void SceneRun::paint(const State& state, const std::vector<DrawList>& ghosts, Image& frame, DrawList* list) {
  canvas_->begin(camera_);
  if (list) {
    BothCanvases both(*canvas_, *list);
    painter_.paint(state.world, state.history, ghosts, both);
  } else {
    painter_.paint(state.world, state.history, ghosts, *canvas_);
  }
  canvas_->finish(frame);
}

Image SceneRun::titleCard() {
  if (!text_) throw std::logic_error("SceneRun::titleCard needs a text renderer");
  return composeSceneCard(def_.render, def_.model.name, def_.model.description, false, camera_.widthPx(), camera_.heightPx(),
                          style_, *text_);
}

Image SceneRun::answerCard() {
  if (!text_) throw std::logic_error("SceneRun::answerCard needs a text renderer");
  return composeSceneCard(def_.render, def_.model.name, def_.model.description, true, camera_.widthPx(), camera_.heightPx(),
                          style_, *text_);
}

DrawList SceneRun::drawListAt(double t, int strobe, std::vector<PlacedText>* placed) {
  DrawList list;
  picturesAt({t}, strobe, [&](size_t, const State& state, const std::vector<DrawList>& ghosts) {
    painter_.paint(state.world, state.history, ghosts, list, placed);
  });
  return list;
}

void SceneRun::framesAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, Image)>& shot) {
  if (!canvas_) throw std::logic_error("SceneRun::framesAt needs a GL context");
  picturesAt(instants, strobe, [&](size_t i, const State& state, const std::vector<DrawList>& ghosts) {
    Image frame;
    paint(state, ghosts, frame);
    shot(i, std::move(frame));
  });
}

void SceneRun::framesAndListsAt(const std::vector<double>& instants, int strobe,
                                const std::function<void(size_t, Image, DrawList)>& shot) {
  if (!canvas_) throw std::logic_error("SceneRun::framesAndListsAt needs a GL context");
  picturesAt(instants, strobe, [&](size_t i, const State& state, const std::vector<DrawList>& ghosts) {
    Image frame;
    DrawList list;
    paint(state, ghosts, frame, &list);
    shot(i, std::move(frame), std::move(list));
  });
}

void SceneRun::drawListsAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, DrawList)>& shot) {
  picturesAt(instants, strobe, [&](size_t i, const State& state, const std::vector<DrawList>& ghosts) {
    DrawList list;
    painter_.paint(state.world, state.history, ghosts, list);
    shot(i, std::move(list));
  });
}

void SceneRun::shotsAt(const std::vector<double>& instants, const std::vector<bool>& pictured,
                       const std::function<void(size_t, const Shot&)>& shot) {
  picturesAt(instants, 0, [&](size_t i, const State& state, const std::vector<DrawList>&) {
    Shot s{state.world, {}, {}};
    if (pictured[i]) {
      painter_.paint(state.world, state.history, {}, s.drawList);
      if (canvas_) paint(state, {}, s.frame);
    }
    shot(i, s);
  });
}

}  // namespace render::frame

#include "render/frame/scene_run.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "render/frame/title_card.h"
#include "render/scene/scene_style.h"
#include "sim/debug/describe.h"
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
      state_(startState(def.model, painter_.historyOptions())),
      text_(text) {
  if (gl && text) canvas_ = std::make_unique<GlCanvas>(*gl, *text, style_);
}

std::vector<DrawList> SceneRun::advance(State& state, double t, int strobe) {
  std::vector<DrawList> ghosts;
  if (strobe > 0 && state.world.time > 0.0) throw std::logic_error("a strobe image needs a fresh run");
  for (int i = 0; i < strobe; ++i) {
    state.world.advanceTo(t * i / strobe, &state.history);
    DrawList ghost;
    const double opacity = kOldestGhost + (kNewestGhost - kOldestGhost) * i / std::max(1, strobe - 1);
    PhysicsDraw physics(ghost);
    sim::debug::describeBodies(state.world, physics, opacity);
    // ghosts of moving bodies only: a static body's ghost would only darken it
    ghosts.emplace_back();
    RoleFilter moving(ghosts.back(), [](Role r) { return r != Role::StaticBody; });
    ghost.replay(moving);
  }
  state.world.advanceTo(t, &state.history);
  return ghosts;
}

Image SceneRun::frameAt(double t, int strobe) {
  if (!canvas_) throw std::logic_error("SceneRun::frameAt needs a GL context");
  const std::vector<DrawList> ghosts = advance(state_, t, strobe);
  return paint(state_, ghosts);
}

void SceneRun::frameAt(double t, Image& frame) {
  if (!canvas_) throw std::logic_error("SceneRun::frameAt needs a GL context");
  paint(state_, advance(state_, t, 0), frame);
}

Image SceneRun::paint(const State& state, const std::vector<DrawList>& ghosts) {
  Image frame;
  paint(state, ghosts, frame);
  return frame;
}

void SceneRun::paint(const State& state, const std::vector<DrawList>& ghosts, Image& frame) {
  canvas_->begin(camera_);
  painter_.paint(state.world, state.history, ghosts, *canvas_);
  canvas_->finish(frame);
}

Image SceneRun::titleCard() {
  if (!text_) throw std::logic_error("SceneRun::titleCard needs a text renderer");
  return composeTitleCard(camera_.widthPx(), camera_.heightPx(), titleOf(def_), def_.model.description, style_, *text_);
}

DrawList SceneRun::drawListAt(double t, int strobe, std::vector<PlacedText>* placed) {
  const std::vector<DrawList> ghosts = advance(state_, t, strobe);
  DrawList list;
  painter_.paint(state_.world, state_.history, ghosts, list, placed);
  return list;
}

void SceneRun::framesAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, Image)>& shot) {
  if (!canvas_) throw std::logic_error("SceneRun::framesAt needs a GL context");
  branchAt(instants, strobe, [&](size_t i, State& state) {
    const std::vector<DrawList> ghosts = advance(state, instants[i], strobe);
    shot(i, paint(state, ghosts));
  });
}

void SceneRun::drawListsAt(const std::vector<double>& instants, int strobe,
                           const std::function<void(size_t, DrawList)>& shot) {
  branchAt(instants, strobe, [&](size_t i, State& state) {
    const std::vector<DrawList> ghosts = advance(state, instants[i], strobe);
    DrawList list;
    painter_.paint(state.world, state.history, ghosts, list);
    shot(i, std::move(list));
  });
}

void SceneRun::shotsAt(const std::vector<double>& instants, const std::vector<bool>& pictured,
                       const std::function<void(size_t, const Shot&)>& shot) {
  branchAt(instants, 0, [&](size_t i, State& state) {
    advance(state, instants[i], 0);
    Shot s{state.world, {}, {}};
    if (pictured[i]) {
      painter_.paint(state.world, state.history, {}, s.drawList);
      if (canvas_) s.frame = paint(state, {});
    }
    shot(i, s);
  });
}

namespace {

// Watches a run that advances to its last instant in one call and keeps, for each instant ahead, a
// copy of the run at its latest step that a fresh run advanced to the instant also takes: every
// step that ends more than the world's time snap before it (advanceTo's own test). Steps are at
// most dt long, so only the steps within 1.5 dt of an instant are copied (and the first state).
template <typename State>
class Brancher : public sim::world::StepObserver {
 public:
  using Reached = std::function<void(size_t, State&)>;
  Brancher(State& run, const std::vector<double>& instants, Reached reached)
      : run_(run), instants_(instants), reached_(std::move(reached)), kept_(instants.size()) {
    order_.resize(instants.size());
    std::iota(order_.begin(), order_.end(), size_t{0});
    std::stable_sort(order_.begin(), order_.end(), [&](size_t a, size_t b) { return instants[a] < instants[b]; });
    for (size_t i : order_) kept_[i] = run_;
  }
  void afterStep(const sim::world::World& world) override {
    run_.history.afterStep(world);
    const double snap = sim::core::settings::kTimeSnap * world.dt;
    // the instants this step reaches: their copies are final
    while (next_ < order_.size() && world.time >= instants_[order_[next_]] - snap) finish(order_[next_++]);
    for (size_t k = next_; k < order_.size() && world.time >= instants_[order_[k]] - 1.5 * world.dt; ++k)
      kept_[order_[k]] = run_;
  }
  void afterEvent(const sim::world::World& world, const sim::world::ImpulseEvent& event) override {
    run_.history.afterEvent(world, event);
  }
  // after the run: every instant not yet reached
  void finishAll() {
    while (next_ < order_.size()) finish(order_[next_++]);
  }

 private:
  void finish(size_t i) {
    State state = std::move(*kept_[i]);
    kept_[i].reset();
    reached_(i, state);
  }

  State& run_;
  const std::vector<double>& instants_;
  Reached reached_;
  std::vector<std::optional<State>> kept_;  // by instant
  std::vector<size_t> order_;               // the instants' indices, earliest first
  size_t next_ = 0;                         // in order_: the first instant not yet reached
};

}  // namespace

void SceneRun::branchAt(const std::vector<double>& instants, int strobe, const Branch& reached) {
  if (instants.empty()) return;
  if (state_.world.time > 0.0) throw std::logic_error("SceneRun::framesAt needs a fresh run");
  Brancher<State> brancher(state_, instants, reached);
  // ghosts split the steps from t/strobe on: each picture is a run of its own from the first state
  if (strobe == 0) state_.world.advanceTo(*std::max_element(instants.begin(), instants.end()), &brancher);
  brancher.finishAll();
}

}  // namespace render::frame

// One run of a scene through the renderer: its world stepped forward to each time asked for (split
// exactly there, whatever the physics step), its history gathered on the way, and the frame at that
// time painted with GL.
#pragma once

#include <functional>
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
  // the same without ghosts into `frame`, whose storage is reused when it has the frame's size (a
  // video's frames, drawn into a few buffers over and over)
  void frameAt(double t, Image& frame);
  // the draw calls of the frame at time t, without GL (the draw-list level of the tests); `placed`
  // (when given) is told where each text went (its box in pixels, the anchor it names)
  DrawList drawListAt(double t, int strobe = 0, std::vector<PlacedText>* placed = nullptr);
  // the frames at each of `instants` (s, in any order) from a fresh run, each exactly what a fresh
  // run's frameAt(t, strobe) paints, told to `shot` with the instant's index, earliest first.
  // Without ghosts the world runs once: a fresh run advanced to t takes the same steps as a longer
  // one up to its last step before t, then a shorter step to t (advanceTo splits the step there), so
  // a copy of this run kept at that step and advanced to t is that fresh run. Ghosts split the steps
  // at t·i/strobe, so with them each picture starts from a copy of the first state. Afterwards this
  // run is spent. Throws sim::world::Diverged.
  void framesAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, Image)>& shot);
  // the same as draw lists, without GL
  void drawListsAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, DrawList)>& shot);
  // what a golden record takes of an instant: the world there (its state hash and trace rows), and
  // when pictured its draw list and, with a GL context, its frame
  struct Shot {
    const sim::world::World& world;
    DrawList drawList;
    Image frame;
  };
  // the shots at each of `instants` from a fresh run, as framesAt reaches them (each the state a fresh
  // run reaches at its instant), those with `pictured[i]` drawn; afterwards this run is spent
  void shotsAt(const std::vector<double>& instants, const std::vector<bool>& pictured,
               const std::function<void(size_t, const Shot&)>& shot);
  // the title card alone (title_card.h), the frame's size; needs the text renderer
  Image titleCard();
  // video frames say when they are slowed (empty: never), see FramePainter
  void showSlowMotion(FramePainter::SlowFactor factorAt) { painter_.showSlowMotion(std::move(factorAt)); }

  const sim::world::World& world() const { return state_.world; }

 private:
  // the world and what its history holds, at one moment of a run (copied to branch the run)
  struct State {
    sim::world::World world;
    History history;
  };
  using Branch = std::function<void(size_t, State&)>;
  // the world built and its history started
  static State startState(const sim::scene::SceneDef& model, History::Options options);
  // `state` advanced to t, and the strobe ghosts on the way
  static std::vector<DrawList> advance(State& state, double t, int strobe);
  // the state from which each instant is reached as a fresh run reaches it (see framesAt)
  void branchAt(const std::vector<double>& instants, int strobe, const Branch& reached);
  // the frame of `state` through GL
  Image paint(const State& state, const std::vector<DrawList>& ghosts);
  void paint(const State& state, const std::vector<DrawList>& ghosts, Image& frame);

  const render::scene::Scene& def_;
  Camera camera_;
  Style style_;
  FramePainter painter_;
  State state_;
  std::unique_ptr<GlCanvas> canvas_;
  TextRenderer* text_;
};

}  // namespace render::frame

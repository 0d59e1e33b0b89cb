// One run of a scene through the renderer: its world stepped on the scene's own step grid (split
// only where the scene splits it: events, force switches, its end), its history gathered on the
// way, and the frame at each time asked for painted with GL. A time between two of the run's steps
// is drawn from a copy of the run advanced to it, never by splitting the run's own step, so that
// the frame times (fps, slow motion, title cards, snapshot times) never change the physics.
#pragma once

#include <functional>
#include <memory>

#include "render/draw/gl_canvas.h"
#include "render/draw/style.h"
#include "render/frame/frame_painter.h"
#include "render/frame/history.h"
#include "render/frame/kept_run.h"
#include "render/frame/stepped_run.h"
#include "sim/world/world.h"

namespace render::frame {

class SceneRun {
 public:
  // `def` must outlive the run; the GL context is the frame's size and current on this thread
  // (without one, only draw lists can be made)
  SceneRun(const render::scene::Scene& def, const render::draw::Camera& camera, const RunSurvey& survey,
           render::draw::GlContext* gl = nullptr, render::draw::TextRenderer* text = nullptr);

  // where the run ends, its last step cut there: the scene's duration unless set (before the first
  // frame) to a video's --duration
  void endAt(double end) { run_.endAt(end); }
  // `observer` (e.g. a trace) is told of every step and event of the run itself, never of the
  // copies drawn between steps; set it before the first frame
  void follow(sim::world::StepObserver* observer) { run_.follow(observer); }
  // the run taken on to its end (what a trace needs after the last picture), the pictures along it
  // not yet taken taken on the way. Throws as frameAt.
  void finish();
  // a picture taken as the run passes instant t, with `strobe` ghosts: exactly what a fresh run's
  // frameAt(t, strobe) paints, without a video's slow-motion note. A video's poster is drawn so from
  // the video's own run, and the scene is stepped once for both. Set before the first frame; `shot`
  // is told the picture by the first picture asked at t′ ≥ t (frameAt, drawListAt, framesAt, …),
  // by takePicturesAlong(), or by finish().
  void pictureAlong(double t, int strobe, std::function<void(render::draw::Image)> shot);
  // the pictures along the run not yet taken, taken: the run stepped only as far as they need
  void takePicturesAlong() { takeAlong(run_.end()); }

  // the frame at time t, which must not be earlier than the last one; with `strobe` > 0, that many
  // earlier poses at t·i/strobe (i = 0 … strobe − 1) drawn fading behind the present one, which
  // needs a fresh run (nothing drawn yet). Throws sim::core::Diverged, ImpactsPileUp.
  render::draw::Image frameAt(double t, int strobe = 0);
  // the same without ghosts into `frame`, whose storage is reused when it has the frame's size (a
  // video's frames, drawn into a few buffers over and over)
  void frameAt(double t, render::draw::Image& frame);
  // the draw calls of the frame at time t, without GL (the draw-list level of the tests); `placed`
  // (when given) is told where each text went (its box in pixels, the anchor it names)
  render::draw::DrawList drawListAt(double t, int strobe = 0, std::vector<PlacedText>* placed = nullptr);
  // the frames at each of `instants` (s, in any order, none earlier than the last frame), each
  // exactly what a fresh run's frameAt(t, strobe) paints, told to `shot` with the instant's index,
  // earliest first: the run goes once through all of them and their ghosts (with ghosts it must be
  // fresh). Throws as frameAt.
  void framesAt(const std::vector<double>& instants, int strobe, const std::function<void(size_t, render::draw::Image)>& shot);
  // the same, each frame with its draw list (what `snapshot --draw-list` writes beside it)
  void framesAndListsAt(const std::vector<double>& instants, int strobe,
                        const std::function<void(size_t, render::draw::Image, render::draw::DrawList)>& shot);
  // the same as draw lists, without GL
  void drawListsAt(const std::vector<double>& instants, int strobe,
                   const std::function<void(size_t, render::draw::DrawList)>& shot);
  // what a golden record takes of an instant: the world there (its state hash and trace rows), and
  // when pictured its draw list and, with a GL context, its frame
  struct Shot {
    const sim::world::World& world;
    render::draw::DrawList drawList;
    render::draw::Image frame;
  };
  // the shots at each of `instants` (in any order, none earlier than the last picture) from the one
  // run, as framesAt reaches them, those with `pictured[i]` drawn. Throws as frameAt.
  void shotsAt(const std::vector<double>& instants, const std::vector<bool>& pictured,
               const std::function<void(size_t, const Shot&)>& shot);
  // the title card alone (title_card.h), the frame's size; needs the text renderer
  render::draw::Image titleCard();
  // the closing card with the poll's answer (`answer_card`), the frame's size; needs the text renderer
  render::draw::Image answerCard();
  // video frames say when they are slowed (empty: never), see FramePainter
  void showSlowMotion(FramePainter::SlowFactor factorAt) { painter_.showSlowMotion(std::move(factorAt)); }

  // the world the last picture was drawn from: the run's own, or its copy between two steps
  const sim::world::World& world() const { return run_.world(); }
  // the run's own world, at its last step
  const sim::world::World& runWorld() const { return run_.runWorld(); }
  // the steps this run took for its pictures: none where the survey kept the run at their instants
  long stepsTaken() const { return run_.stepsTaken(); }

 private:
  using Run = PlanarRun;
  using State = Run::State;
  // the world built and its history started
  static State startState(const sim::scene::SceneDef& model, History::Options options);
  // a time a picture needs: instant `instant` itself (ghost −1), or its ghost i at t·i/strobe
  struct Need {
    double time;
    size_t instant;
    int ghost;
  };
  // every time the pictures at `instants` need, earliest first, a picture after its ghosts
  static std::vector<Need> needsOf(const std::vector<double>& instants, int strobe);
  // the pictures along the run (pictureAlong) whose times are at most `upTo`
  void takeAlong(double upTo);
  struct Along {
    std::vector<Need> needs;
    size_t next = 0;  // the first need not yet reached
    int strobe = 0;
    std::vector<render::draw::DrawList> ghosts;
    std::function<void(render::draw::Image)> shot;
  };
  // ghost i of `strobe`: the moving bodies of a state, fading
  static render::draw::DrawList ghostOf(const State& state, int i, int strobe);
  // the pictures at `instants`, each with its ghosts, from the one run, earliest first
  void picturesAt(const std::vector<double>& instants, int strobe,
                  const std::function<void(size_t, const State&, const std::vector<render::draw::DrawList>&)>& picture);
  // the frame of `state` through GL (and recorded into `list`, when given)
  void paint(const State& state, const std::vector<render::draw::DrawList>& ghosts, render::draw::Image& frame,
             render::draw::DrawList* list = nullptr);

  const render::scene::Scene& def_;
  render::draw::Camera camera_;
  render::draw::Style style_;
  FramePainter painter_;
  Run run_;
  std::vector<Along> along_;  // the pictures taken along the run, in the order asked
  std::unique_ptr<render::draw::GlCanvas> canvas_;
  render::draw::TextRenderer* text_;
};

}  // namespace render::frame

// A run's pictures at several instants from one run of its world (scene_run.cpp): each must be the
// very frame a fresh run advanced to that instant draws, to the last bit of every coordinate, since
// the PNGs of `snapshot` and the poll panels are compared byte for byte; and the run's own steps are
// those of the scene's grid whatever the pictures' times, as `simulate` takes them.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "render/frame/scene_run.h"
#include "render/frame/survey.h"
#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "support/drawn_scene.h"

using render::draw::DrawList;
using render::frame::SceneRun;

namespace {

// every call with its numbers in full (DrawList::lines rounds them to 6 digits)
std::string exact(const DrawList& list) {
  std::string s;
  char buf[64];
  for (const DrawList::Call& c : list.calls()) {
    std::snprintf(buf, sizeof buf, "%d %d/%d/%d/%.17g ", static_cast<int>(c.kind), static_cast<int>(c.style.role), c.style.body,
                  c.style.color, c.style.opacity);
    s += buf;
    for (const sim::core::Vec2& p : c.points) {
      std::snprintf(buf, sizeof buf, "(%.17g,%.17g) ", p.x(), p.y());
      s += buf;
    }
    std::snprintf(buf, sizeof buf, "r%.17g ", c.radius);
    s += buf + c.text + "\n";
  }
  return s;
}

struct Variant {
  render::scene::Scene def;
  render::frame::RunSurvey survey;
  render::draw::Camera camera;
};

Variant variant(const std::string& file, const std::string& name) {
  render::scene::Scene def = drawn_scene::loadFile(std::string(RIGIDREEL_SOURCE_DIR) + "/" + file, name);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  return {def, survey, render::frame::cameraFor(def, survey)};
}

// the frame of a fresh run at t, as `snapshot` drew every picture before
std::string fresh(const Variant& v, double t, int strobe) {
  SceneRun run(v.def, v.camera, v.survey);
  return exact(run.drawListAt(t, strobe));
}

// the frames at `instants` from one run
std::map<size_t, std::string> branched(const Variant& v, const std::vector<double>& instants, int strobe) {
  SceneRun run(v.def, v.camera, v.survey);
  std::map<size_t, std::string> frames;
  std::vector<double> order;
  run.drawListsAt(instants, strobe, [&](size_t i, DrawList list) {
    CHECK(frames.count(i) == 0);
    frames[i] = exact(list);
    order.push_back(instants[i]);
  });
  CHECK(frames.size() == instants.size());
  CHECK(std::is_sorted(order.begin(), order.end()));
  return frames;
}

void checkSameAsFresh(const Variant& v, const std::vector<double>& instants, int strobe = 0) {
  const std::map<size_t, std::string> frames = branched(v, instants, strobe);
  for (size_t i = 0; i < instants.size(); ++i) {
    CAPTURE(instants[i]);
    CHECK(frames.at(i) == fresh(v, instants[i], strobe));
  }
}

}  // namespace

TEST_CASE("pictures at several instants from one run are the fresh runs' frames, bit for bit") {
  SUBCASE("explicit Euler with a coarse step, where splitting a step moves the bodies by centimeters") {
    const Variant v = variant("scenes/lecture/10a_energy_gain.yaml", "explicit_euler");
    // off the 0.05 s grid, on it, the start, the end, twice the same, out of order
    checkSameAsFresh(v, {4.99, 0.0, 2.5, 0.05, 1.234567, 1.234567, 5.0, 0.01});
  }
  SUBCASE("the event method at its impacts and just around them") {
    const Variant v = variant("scenes/three_collisions_poll.yaml", "C");
    REQUIRE(!v.survey.impactTimes.empty());
    std::vector<double> instants;
    for (double t : v.survey.impactTimes) instants.insert(instants.end(), {t, t - 1e-4, t + 1e-4, t - 0.5e-3});
    instants.push_back(v.def.model.duration);
    checkSameAsFresh(v, instants);
  }
  SUBCASE("a timed impulse, at and before its instant, with rk4 at dt = 1 ms") {
    const Variant v = variant("scenes/poll_bar_impulse.yaml", "end");
    checkSameAsFresh(v, {0.5, 0.5 - 1e-12, 0.5 + 1e-13, 0.4999, 0.5001, 0.0005, 1e-13, 2.0});
  }
  SUBCASE("a stack under the sequential solver, its history of contacts held") {
    const Variant v = variant("scenes/box_stack.yaml", "sequential");
    checkSameAsFresh(v, {0.1, 1.0 / 3.0, 1.0, 0.5});
  }
  SUBCASE("strobe ghosts: each picture from the first state") {
    const Variant v = variant("scenes/poll_bar_impulse.yaml", "end");
    checkSameAsFresh(v, {2.0, 0.7, 1.3}, 4);
  }
}

TEST_CASE("one run asked for one instant after another draws each as a fresh run does") {
  // explicit Euler at dt = 0.05 s: a step split at 2.51 s would carry its difference on to 4.99 s
  const Variant v = variant("scenes/lecture/10a_energy_gain.yaml", "explicit_euler");
  SceneRun run(v.def, v.camera, v.survey);
  (void)run.drawListAt(2.51);
  CHECK(run.runWorld().time == doctest::Approx(2.5).epsilon(1e-12));
  CHECK(run.world().time == 2.51);
  CHECK(exact(run.drawListAt(4.99)) == fresh(v, 4.99, 0));
}

namespace {

// every step's time and state, as the run takes it
struct StepLog : sim::world::StepObserver {
  std::vector<std::string> rows;
  void afterStep(const sim::world::World& w) override { log(w, "step"); }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent&) override { log(w, "event"); }
  void log(const sim::world::World& w, const char* what) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s %.17g %016llx", what, w.time, static_cast<unsigned long long>(sim::world::stateHash(w)));
    rows.emplace_back(buf);
  }
};

}  // namespace

TEST_CASE("the run's own steps are the scene's grid, whatever the pictures' times") {
  // a timed impulse between grid points (rk4, dt 1 ms) and the event method's impacts
  for (const auto& [fileBound, name] :
       {std::pair{"scenes/poll_bar_impulse.yaml", "end"}, std::pair{"scenes/three_collisions_poll.yaml", "C"}}) {
    // a copy: clang 14 cannot capture a structured binding in CAPTURE (make sanitize builds with it)
    const char* const file = fileBound;
    CAPTURE(file);
    const Variant v = variant(file, name);
    StepLog alone;
    sim::world::World world = sim::scene::buildWorld(v.def.model);
    world.advanceTo(v.def.model.duration, &alone);
    // pictures at 1/60 s, at odd instants, with ghosts, then the rest of the run
    StepLog drawn;
    SceneRun run(v.def, v.camera, v.survey);
    run.follow(&drawn);
    std::vector<double> instants;
    for (int k = 0; k * (1.0 / 60.0) < v.def.model.duration; ++k) instants.push_back(k / 60.0);
    instants.insert(instants.end(), {0.123456, 0.5 + 1e-7, v.def.model.duration});
    run.drawListsAt(instants, 3, [](size_t, DrawList) {});
    run.finish();
    REQUIRE(alone.rows.size() > 100);
    CHECK(drawn.rows == alone.rows);
  }
}

TEST_CASE("a run asked for an instant before its own time refuses") {
  const Variant v = variant("scenes/poll_bar_impulse.yaml", "end");
  SceneRun run(v.def, v.camera, v.survey);
  (void)run.drawListAt(0.5);
  CHECK_THROWS_AS(run.drawListsAt({0.25}, 0, [](size_t, DrawList) {}), std::logic_error);
  CHECK_THROWS_AS(run.drawListsAt({1.0}, 2, [](size_t, DrawList) {}), std::logic_error);
}

namespace {

// frame k of a video at 1/60 s into `frame` from `run`, up to (not including) `until`
void drawVideo(SceneRun& run, double until) {
  render::draw::Image frame;
  for (int k = 0; k / 60.0 < until; ++k) run.frameAt(k / 60.0, frame);
}

}  // namespace

TEST_CASE("a picture taken along a video's run is the fresh run's frame, byte for byte") {
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  struct Case {
    const char* file;
    const char* variant;
    double at;
    int strobe;
  };
  // a poll's poster at the start, one mid-run with ghosts, one at the end, one between grid points
  for (const Case& c :
       {Case{"scenes/three_collisions_poll.yaml", "C", 0.0, 0}, Case{"scenes/poll_bar_impulse.yaml", "end", 1.3, 4},
        Case{"scenes/three_collisions_poll.yaml", "C", -1.0, 0}, Case{"scenes/poll_bar_impulse.yaml", "end", 0.5 + 1e-7, 0}}) {
    CAPTURE(c.file);
    CAPTURE(c.at);
    Variant v = variant(c.file, c.variant);
    v.def.render.width = 320, v.def.render.height = 180;
    v.camera = render::frame::cameraFor(v.def, v.survey);
    const double at = c.at < 0.0 ? v.def.model.duration : c.at;
    SceneRun fresh(v.def, v.camera, v.survey, &gl, &text);
    const render::draw::Image want = fresh.frameAt(at, c.strobe);
    // (the note would show: a fresh run told of slow motion draws another picture)
    SceneRun slowed(v.def, v.camera, v.survey, &gl, &text);
    slowed.showSlowMotion([](double) { return 4.0; });
    CHECK(slowed.frameAt(at, c.strobe).rgba != want.rgba);

    // the video's frames say "slow motion", the poster taken among them must not
    SceneRun run(v.def, v.camera, v.survey, &gl, &text);
    run.showSlowMotion([](double) { return 4.0; });
    render::draw::Image got;
    int taken = 0;
    run.pictureAlong(at, c.strobe, [&](render::draw::Image picture) {
      got = std::move(picture);
      ++taken;
    });
    drawVideo(run, v.def.model.duration);
    run.finish();
    CHECK(taken == 1);
    REQUIRE(got.width == want.width);
    CHECK(got.rgba == want.rgba);
    // and the video's own last frame is what a run without the poster draws
    const double last = std::floor(v.def.model.duration * 60.0 - 1e-9) / 60.0;
    SceneRun plain(v.def, v.camera, v.survey, &gl, &text);
    plain.showSlowMotion([](double) { return 4.0; });
    render::draw::Image plainFrame, alongFrame;
    plain.frameAt(last, plainFrame);
    SceneRun again(v.def, v.camera, v.survey, &gl, &text);
    again.showSlowMotion([](double) { return 4.0; });
    again.pictureAlong(at, c.strobe, [](render::draw::Image) {});
    drawVideo(again, last);
    again.frameAt(last, alongFrame);
    CHECK(alongFrame.rgba == plainFrame.rgba);
  }
}

TEST_CASE("a picture along a run is asked before its first frame") {
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  const Variant v = variant("scenes/poll_bar_impulse.yaml", "end");
  SceneRun run(v.def, v.camera, v.survey, &gl, &text);
  render::draw::Image frame;
  run.frameAt(0.25, frame);
  CHECK_THROWS_AS(run.pictureAlong(1.0, 0, [](render::draw::Image) {}), std::logic_error);
  SceneRun listsOnly(v.def, v.camera, v.survey);
  CHECK_THROWS_AS(listsOnly.pictureAlong(1.0, 0, [](render::draw::Image) {}), std::logic_error);
}

TEST_CASE("a picture along a run is taken by any picture past it, or by takePicturesAlong, never twice") {
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  Variant v = variant("scenes/poll_bar_impulse.yaml", "end");
  v.def.render.width = 320, v.def.render.height = 180;
  v.camera = render::frame::cameraFor(v.def, v.survey);
  SceneRun fresh(v.def, v.camera, v.survey, &gl, &text);
  const render::draw::Image want = fresh.frameAt(0.5 + 1e-7, 3);

  // a draw list past the instant takes it first (the run never passes a picture it owes)
  SceneRun run(v.def, v.camera, v.survey, &gl, &text);
  std::vector<render::draw::Image> got;
  run.pictureAlong(0.5 + 1e-7, 3, [&](render::draw::Image picture) { got.push_back(std::move(picture)); });
  (void)run.drawListAt(1.0);
  REQUIRE(got.size() == 1);
  CHECK(got[0].rgba == want.rgba);
  run.takePicturesAlong();
  run.finish();
  CHECK(got.size() == 1);

  // takePicturesAlong steps only as far as the picture needs
  SceneRun early(v.def, v.camera, v.survey, &gl, &text);
  int taken = 0;
  early.pictureAlong(0.25, 0, [&](render::draw::Image) { ++taken; });
  early.takePicturesAlong();
  CHECK(taken == 1);
  CHECK(early.runWorld().time <= 0.25 + 1e-12);
}

// The survey's run kept at the pictures' instants (kept_run.cpp): a drawing that goes on from the
// kept states draws what a run of its own draws, bit for bit, and steps the scene no further.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "render/frame/kept_run.h"
#include "render/frame/scene_run.h"
#include "render/frame/survey.h"
#include "sim/scene/scene_build.h"
#include "support/drawn_scene.h"

namespace {

// a ball and a spinning box dropped on a floor, the box struck at 0.3 s: impacts, contacts held and
// fading, an event's arrow, trails and a body point's path, at 200 steps a second
const std::string kScene =
    "name: kept\n"
    "duration: 2\n"
    "world: {gravity: [0, -9.81], restitution: 0.5}\n"
    "sim: {collisions: event, dt: 0.005}\n"
    "bodies:\n"
    "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
    "  - {name: ball, shape: {circle: 0.25}, position: [0, 1], velocity: [1, 0]}\n"
    "  - {name: box, shape: {box: [0.4, 0.3]}, position: [-1, 0.8], angle: 0.4, velocity: [0.5, 0], angular_velocity: 2}\n"
    "events:\n"
    "  - {time: 0.3, body: box, impulse: [0.5, 1], point: [0.1, 0.1]}\n"
    "render:\n"
    "  size: [640, 360]\n"
    "  trails: true\n"
    "  impact_values: true\n"
    "  arrows: [{body: box, show: path, at: [0.2, 0.15]}]\n";

struct Drawing {
  std::vector<std::string> lists;  // the draw list at each instant, as text
  long steps = 0;                  // the steps the drawing's run took
  long surveySteps = 0;
  size_t kept = 0;  // states the survey kept
};

// the scene surveyed (kept at `instants` when `keep`), then drawn at `instants`
Drawing drawn(const render::scene::Scene& def, const std::vector<double>& instants, bool keep,
              sim::world::StepObserver* follower = nullptr) {
  const render::frame::RunSurvey survey = render::frame::surveyRun(def, -1.0, keep ? instants : std::vector<double>{});
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  if (follower) run.follow(follower);
  Drawing d;
  run.drawListsAt(instants, 0, [&](size_t, render::draw::DrawList list) { d.lists.push_back(list.toText()); });
  d.steps = run.stepsTaken();
  d.surveySteps = survey.steps;
  d.kept = survey.kept ? survey.kept->states.size() : 0;
  return d;
}

// the steps simulate takes over the whole scene
long simulateSteps(const render::scene::Scene& def) {
  sim::world::World world = sim::scene::buildWorld(def.model);
  world.advanceTo(def.model.duration);
  return world.steps;
}

// k / 40 s for k = 0 … 80 (every fifth step), shifted by `shift`
std::vector<double> frames(double shift) {
  std::vector<double> t;
  for (int k = 0; k <= 80; ++k) t.push_back(std::min(2.0, k / 40.0 + shift));
  return t;
}

}  // namespace

TEST_CASE("a drawing that goes on from the kept run is the fresh run's, bit for bit, and takes no step") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  const Drawing kept = drawn(def, frames(0.0), true), fresh = drawn(def, frames(0.0), false);
  REQUIRE(kept.lists.size() == 81);
  CHECK(kept.lists == fresh.lists);
  // the scene stepped once: by the survey, as simulate steps it; the drawing took none
  const long once = simulateSteps(def);
  CHECK(once == 400);
  CHECK(kept.surveySteps == once);
  CHECK(kept.steps == 0);
  CHECK(kept.kept == 80);  // every instant but the start, where the run begins anyway
  // without kept states the drawing steps the whole scene a second time
  CHECK(fresh.kept == 0);
  CHECK(fresh.steps == once);
  // the frames show what the test is about: impacts, the event's arrow, trails and the path
  const std::string all = [&] {
    std::string s;
    for (const std::string& list : kept.lists) s += list;
    return s;
  }();
  for (const char* role : {"Impulse", "ContactNormal", "Trail", "Label"}) {
    CAPTURE(role);
    CHECK(all.find(role) != std::string::npos);
  }
}

TEST_CASE("instants between two steps each take only their part step from the kept state") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  // half a step past each frame of the grid
  const std::vector<double> instants = frames(0.0025);
  const Drawing kept = drawn(def, instants, true), fresh = drawn(def, instants, false);
  CHECK(kept.lists == fresh.lists);
  CHECK(kept.steps == static_cast<long>(instants.size()) - 1);  // the last is the end, on the grid
  CHECK(fresh.steps == kept.steps + simulateSteps(def));
}

TEST_CASE("a run followed step by step (a trace) steps on its own: its follower is told of every step") {
  struct Count : sim::world::StepObserver {
    long steps = 0;
    void afterStep(const sim::world::World&) override { ++steps; }
  } count;
  const render::scene::Scene def = drawn_scene::load(kScene);
  const Drawing kept = drawn(def, frames(0.0), true, &count);
  CHECK(count.steps == simulateSteps(def));
  CHECK(kept.steps == count.steps);
  CHECK(kept.lists == drawn(def, frames(0.0), false).lists);
}

TEST_CASE("past the bound on the kept paths nothing more is kept, and the drawing steps the rest alike") {
  // 10 bodies over 30,000 steps: trails of every step's point outgrow render::scene::kKeptPathBytes
  std::string yaml = "name: many\nduration: 3\nworld: {gravity: [0, 0]}\nsim: {dt: 0.0001}\nbodies:\n";
  for (int i = 0; i < 10; ++i)
    yaml += "  - {name: b" + std::to_string(i) + ", shape: {circle: 0.1}, position: [" + std::to_string(i) +
            ", 0], velocity: [0.3, " + std::to_string(0.1 * i) + "], angular_velocity: 1}\n";
  yaml += "render: {size: [320, 180], trails: true}\n";
  const render::scene::Scene def = drawn_scene::load(yaml);
  std::vector<double> instants;
  for (int k = 0; k <= 30; ++k) instants.push_back(0.1 * k);
  const Drawing kept = drawn(def, instants, true), fresh = drawn(def, instants, false);
  CHECK(kept.kept > 0);
  CHECK(kept.kept < instants.size());
  CHECK(kept.steps > 0);
  CHECK(kept.steps < fresh.steps);
  // the trails after the last kept state go on as a run of the frame's own spacing keeps them
  CHECK(kept.lists == fresh.lists);
}

TEST_CASE("a state is kept only where it saves 4 steps: instants a step apart keep every fourth") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  std::vector<double> instants;
  for (int k = 1; k <= 40; ++k) instants.push_back(0.005 * k);
  const Drawing kept = drawn(def, instants, true), fresh = drawn(def, instants, false);
  CHECK(kept.kept == 10);
  CHECK(kept.lists == fresh.lists);
  // the run steps the three steps between kept states itself
  CHECK(kept.steps == 30);
  CHECK(fresh.steps == 40);
}

TEST_CASE("a run that ends elsewhere, or records something else, than the survey's steps on its own") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  const std::vector<double> instants = frames(0.0);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def, -1.0, instants);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  REQUIRE(survey.kept);
  // a video cut at 1 s: its last step is cut elsewhere than the survey's, whose states it leaves
  render::frame::SceneRun cut(def, camera, survey);
  cut.endAt(1.0);
  cut.drawListAt(1.0);
  CHECK(cut.stepsTaken() == 200);
  // a history that keeps no trails is not the one the survey kept
  render::scene::Scene plain = def;
  plain.render.trails = false;
  render::frame::SceneRun other(plain, camera, survey);
  const std::string got = other.drawListAt(1.0).toText();
  CHECK(other.stepsTaken() == 200);
  render::frame::SceneRun fresh(plain, camera, render::frame::surveyRun(plain));
  CHECK(got == fresh.drawListAt(1.0).toText());
}

// The recording loop: frame k at exactly k / fps, every frame handed on in order, a failing sink
// stops the loop with its error, and PNG frames are numbered for ffmpeg's image reader.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>

#include "render/video/recorder.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"

namespace fs = std::filesystem;

namespace {

struct Collect : render::video::FrameSink {
  std::vector<long> indices;
  std::vector<render::draw::Image> images;
  void frame(long index, const render::draw::Image& image) override {
    indices.push_back(index);
    images.push_back(image);
  }
};

struct Fail : render::video::FrameSink {
  void frame(long index, const render::draw::Image&) override {
    if (index == 2) throw std::runtime_error("disk full");
  }
};

const char* const kScene =
    "duration: 1\n"
    "bodies:\n"
    "  - {name: ball, shape: {circle: 0.5}, velocity: [1, 0]}\n"
    "render: {size: [64, 48], camera: {center: [0.5, 0], height: 2}}\n";

}  // namespace

TEST_CASE("frames come in order, one per k / fps, and the run ends at the last one's time") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::draw::GlContext gl(64, 48);
  render::draw::TextRenderer text;
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
  Collect sink;
  long reported = 0;
  render::video::record(run, render::video::TimeMap(0.5), 10.0, {&sink}, [&](long done) { reported = done; });
  CHECK(sink.indices == std::vector<long>{0, 1, 2, 3, 4});
  CHECK(reported == 5);
  CHECK(run.world().time == doctest::Approx(0.4).epsilon(1e-15));
  // the ball moves, so consecutive frames differ
  CHECK(sink.images[0] != sink.images[4]);
}

TEST_CASE("a sink that fails stops the recording with its error") {
  const render::scene::Scene def = drawn_scene::load(kScene);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::draw::GlContext gl(64, 48);
  render::draw::TextRenderer text;
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
  Fail sink;
  CHECK_THROWS_WITH_AS(render::video::record(run, render::video::TimeMap(6.0), 10.0, {&sink}), "disk full", std::runtime_error);
  CHECK(run.world().time < 1.0);
}

TEST_CASE("PNG frames are numbered with at least five digits") {
  const fs::path dir = fs::temp_directory_path() / ("rigidreel_recorder_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  render::video::PngFrames frames(dir.string(), 12);
  CHECK(frames.pattern() == "frame-%05ld.png");
  frames.frame(7, render::draw::Image(4, 4));
  CHECK(fs::exists(dir / "frame-00007.png"));
  CHECK(render::video::PngFrames(dir.string(), 1234567).pattern() == "frame-%07ld.png");
  fs::remove_all(dir);
}

TEST_CASE("a title card opens the video, painted once and held; slow motion stretches the run") {
  // 0.2 s of card, then 1 s of run whose [0.2, 0.4) takes twice as long: 1.4 s, 14 frames at 10 fps
  const render::scene::Scene def = drawn_scene::load(
      "duration: 1\n"
      "bodies:\n"
      "  - {name: ball, shape: {circle: 0.5}, velocity: [1, 0]}\n"
      "render: {size: [64, 48], camera: {center: [0.5, 0], height: 2}, title_card: 0.2,\n"
      "         slow_motion: {factor: 2, from: 0.2, to: 0.4}}\n");
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const render::video::TimeMap map = render::video::timeMapFor(def.render, survey.impactTimes, def.model.duration);
  render::draw::GlContext gl(64, 48);
  render::draw::TextRenderer text;
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
  Collect sink;
  render::video::record(run, map, 10.0, {&sink});
  REQUIRE(sink.indices.size() == 14);
  CHECK(sink.images[0] == sink.images[1]);
  CHECK(sink.images[1] != sink.images[2]);
  // the last frame, video time 1.3 s: 0.2 s of card, 0.2 s of run, 0.4 s slowed to 0.4, 0.5 s more
  CHECK(run.world().time == doctest::Approx(0.9).epsilon(1e-12));
}

TEST_CASE("an answer card closes the video: the run's frames, then the card held, painted once") {
  // 1 s of run, then 0.5 s of answer: 15 frames at 10 fps, the last 5 the card
  const render::scene::Scene def = drawn_scene::load(
      "duration: 1\n"
      "answer: It rolls on.\n"
      "bodies:\n"
      "  - {name: ball, shape: {circle: 0.5}, velocity: [1, 0]}\n"
      "render: {size: [320, 180], camera: {center: [0.5, 0], height: 2}, answer_card: 0.5}\n");
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const render::video::TimeMap map = render::video::timeMapFor(def.render, survey.impactTimes, def.model.duration);
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
  Collect sink;
  render::video::record(run, map, 10.0, {&sink});
  REQUIRE(sink.indices.size() == 15);
  CHECK(sink.images[8] != sink.images[9]);
  CHECK(sink.images[9] != sink.images[10]);
  for (int k = 11; k < 15; ++k) CHECK(sink.images[k] == sink.images[10]);
  CHECK(sink.images[10] == run.answerCard());
  CHECK(run.world().time == doctest::Approx(0.9).epsilon(1e-12));
}

// A 3D run's picture taken along a video's run (scene_run3d.cpp): the fresh run's frame at that
// instant, byte for byte, without the video's slow-motion note, and the video's frames unchanged by it.
#include "render/frame3d/scene_run3d.h"

#include <doctest/doctest.h>

#include <cmath>

#include "sim/yaml/scene_source.h"

using namespace render::frame3d;
using render::draw3d::Camera3d;

namespace {

const char* const kTop = R"(
dimensions: 3
duration: 0.5
sim: {integrator: splitting, dt: 0.001}
bodies:
  - {name: top, shape: {ellipsoid: [0.3, 0.3, 0.1]}, density: 100, orientation: {axis: [1, 0, 0], angle: 0.3},
     angular_velocity: [0.5, 0, 4], label: top}
render:
  size: [320, 180]
  arrows:
    - {body: top, show: omega}
)";

std::function<double(double)> slowed() {
  return [](double) { return 4.0; };
}

}  // namespace

TEST_CASE("a 3D picture taken along a video's run is the fresh run's frame, byte for byte") {
  const render::scene3d::Scene def = render::scene3d::readScene(sim::yaml::sceneSourceText(kTop, "inline.yaml"));
  const RunSurvey3d survey = surveyRun(def);
  const Camera3d camera = cameraFor(def, survey);
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  // a question's poster at the start, one between grid points, one at the end
  for (const double at : {0.0, 0.2345678, 0.5}) {
    CAPTURE(at);
    SceneRun3d fresh(def, camera, survey, &gl, &text);
    const render::draw::Image want = fresh.frameAt(at);
    SceneRun3d noted(def, camera, survey, &gl, &text);
    noted.showSlowMotion(slowed());
    CHECK(noted.frameAt(at).rgba != want.rgba);

    SceneRun3d run(def, camera, survey, &gl, &text);
    run.showSlowMotion(slowed());
    render::draw::Image got;
    int taken = 0;
    run.pictureAlong(at, [&](render::draw::Image picture) {
      got = std::move(picture);
      ++taken;
    });
    render::draw::Image frame;
    for (int k = 0; k / 60.0 < def.model.duration; ++k) run.frameAt(k / 60.0, frame);
    run.finish();
    CHECK(taken == 1);
    CHECK(got.rgba == want.rgba);
    // the video's last frame, as a run without the poster draws it
    SceneRun3d plain(def, camera, survey, &gl, &text);
    plain.showSlowMotion(slowed());
    CHECK(plain.frameAt(std::floor(def.model.duration * 60.0 - 1e-9) / 60.0).rgba == frame.rgba);
  }
}

TEST_CASE("a 3D picture along a run is asked before its first frame") {
  const render::scene3d::Scene def = render::scene3d::readScene(sim::yaml::sceneSourceText(kTop, "inline.yaml"));
  const RunSurvey3d survey = surveyRun(def);
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  SceneRun3d run(def, cameraFor(def, survey), survey, &gl, &text);
  (void)run.frameAt(0.1);
  CHECK_THROWS_AS(run.pictureAlong(0.3, [](render::draw::Image) {}), std::logic_error);
}

TEST_CASE("a 3D drawing that goes on from the survey's kept run is the fresh run's, and takes no step") {
  // the top with its trail and the cone ω sweeps: paths of every step's point, respaced when taken up
  std::string yaml = kTop;
  yaml.replace(yaml.find("  arrows:\n"), 10, "  trails: true\n  arrows:\n    - {body: top, show: omega_path}\n");
  const render::scene3d::Scene def = render::scene3d::readScene(sim::yaml::sceneSourceText(yaml, "inline.yaml"));
  std::vector<double> instants;
  for (int k = 0; k <= 20; ++k) instants.push_back(k / 40.0);
  const RunSurvey3d kept = surveyRun(def, -1.0, instants), plain = surveyRun(def);
  REQUIRE(kept.kept);
  CHECK(kept.kept->states.size() == instants.size() - 1);  // not the start: the run begins there
  CHECK(kept.steps == 500);
  CHECK(plain.steps == 500);
  const Camera3d camera = cameraFor(def, plain);
  SceneRun3d fromKept(def, camera, kept), fresh(def, camera, plain);
  for (double t : instants) {
    CAPTURE(t);
    const std::string want = fresh.drawListAt(t).toText();
    CHECK(fromKept.drawListAt(t).toText() == want);
  }
  CHECK(fromKept.stepsTaken() == 0);
  CHECK(fresh.stepsTaken() == 500);
}

// The pixels of 3D frames against tests/golden/ (the tolerance of tests/golden/README.md): a box
// and an ellipsoid in perspective with the body axes, ω and L, a body point's path, a trail and the
// state text (the energy panel is the 2D one's, and in the lecture goldens); and the same scene
// drawn twice gives the same bytes.
#include <doctest/doctest.h>

#include "render/frame3d/scene_run3d.h"
#include "sim/yaml/scene_source.h"
#include "support/golden_compare.h"

using namespace render::frame3d;

namespace {

const char* const kScene = R"(
dimensions: 3
duration: 1.5
sim: {integrator: rk4, dt: 0.005}
bodies:
  - {name: box, shape: {box: [0.4, 0.8, 1.2]}, position: [-0.7, 0, 0], orientation: {axis: [1, 1, 0], angle: 0.5},
     velocity: [0.2, 0, 0], angular_velocity: [0.3, 2.0, 0.3], color: "#3b6ea5", label: box}
  - {name: egg, shape: {ellipsoid: [0.35, 0.25, 0.5]}, position: [0.9, 0.2, 0], angular_velocity: [0, 0, 1.5],
     color: "#f28e2b", label: ""}
render:
  size: [320, 180]
  line_width: 1.5
  trails: true
  arrows:
    - {body: box, show: axes}
    - {body: box, show: omega}
    - {body: box, show: angular_momentum}
    - {body: box, show: path, at: [0.2, 0.4, 0.6]}
    - {body: egg, show: state}
)";

render::draw::Image frame(double t) {
  const render::scene3d::Scene def = render::scene3d::readScene(sim::yaml::sceneSourceText(kScene, "inline.yaml"));
  const RunSurvey3d survey = surveyRun(def);
  render::draw::GlContext gl(def.render.width, def.render.height);
  render::draw::TextRenderer text;
  SceneRun3d run(def, cameraFor(def, survey), survey, &gl, &text);
  return run.frameAt(t);
}

}  // namespace

TEST_CASE("golden: a 3D frame in perspective with its overlays") { golden::checkGolden("space3d", frame(1.0)); }

TEST_CASE("a 3D frame drawn twice is the same, byte for byte") { CHECK(frame(0.5) == frame(0.5)); }

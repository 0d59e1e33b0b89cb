// A 3D scene's render: block: the keys it shares with 2D, the perspective camera and the 3D arrows,
// each fault at its FILE:LINE:COL, and the 2D-only keys and `panels: impacts` refused with a reason.
#include "render/scene3d/scene.h"

#include <doctest/doctest.h>

#include "support/scene_error_check.h"

using namespace render::scene3d;
using sim::world3d::Vec3;

namespace {

const char* const kFile = "inline.yaml";

Scene load(const std::string& text, const std::string& variant = "") {
  return readScene(sim::yaml::sceneSourceText(text, kFile, variant));
}

void expectSceneError(const std::string& text, int line, int column, std::initializer_list<std::string> words) {
  scene_errors::expectSceneError([](const std::string& t, const std::string& f,
                                    const std::string& v) { return readScene(sim::yaml::sceneSourceText(t, f, v)); },
                                 kFile, text, line, column, words);
}

// a 3D scene with one body `top` on lines 1-4; the render: block follows on line 5
const std::string kScene =
    "dimensions: 3\n"
    "duration: 2\n"
    "bodies:\n"
    "  - {name: top, shape: {ellipsoid: [0.3, 0.3, 0.1]}, color: \"#3b6ea5\", label: spinning top}\n";

}  // namespace

TEST_CASE("a 3D render: block: shared keys, a fixed camera, arrows and scales") {
  const Scene s = load(kScene + R"(render:
  size: [640, 360]
  fps: 30
  energy: true
  trails: true
  title_card: 1
  camera: {eye: [2, -3, 1], target: [0, 0, 0.1], fov: 40}
  arrows:
    - {body: top, show: axes}
    - {body: top, show: omega, value: true}
    - {body: top, show: angular_momentum, color: "#000000"}
    - {body: top, show: path, at: [0.3, 0, 0]}
    - {body: top, show: state}
  omega_scale: 0.1
  world_axes: false
)");
  CHECK(s.render.width == 640);
  CHECK(s.render.fps == 30);
  CHECK(s.render.overlays.energy);
  CHECK(s.render.trails);
  CHECK(s.render.titleCard == 1.0);
  REQUIRE(s.render.bodies.size() == 1);
  CHECK(s.render.bodies[0].color == "#3b6ea5");
  CHECK(s.render.bodies[0].label == "spinning top");
  CHECK_FALSE(s.space.camera.automatic);
  CHECK(s.space.camera.eye == Vec3(2, -3, 1));
  CHECK(s.space.camera.up == Vec3::UnitZ());
  CHECK(s.space.camera.fov == 40.0);
  REQUIRE(s.space.arrows.size() == 5);
  CHECK(s.space.arrows[1].show == Arrow3dDef::Show::Omega);
  CHECK(s.space.arrows[1].value);
  CHECK(s.space.arrows[2].color == "#000000");
  CHECK(s.space.arrows[3].at == Vec3(0.3, 0, 0));
  CHECK(s.space.arrows[4].show == Arrow3dDef::Show::State);
  CHECK(s.space.omegaScale == 0.1);
  CHECK_FALSE(s.space.worldAxes);
  // the style: the body's own color, and the black of the L arrow
  const render::draw::Style style = makeStyle(s, 360);
  CHECK(style.bodies[0].r == doctest::Approx(0x3b / 255.0));
  REQUIRE(style.arrows.size() == 5);
  CHECK(style.arrows[2].a == 1.0);
  CHECK(style.arrows[0].a == 0.0);
}

TEST_CASE("the automatic camera by default, or along a direction; panels default to the duration with variants") {
  const Scene plain = load(kScene);
  CHECK(plain.space.camera.automatic);
  CHECK(plain.space.worldAxes);
  const Scene along = load(kScene + "render: {camera: {direction: [0, -1, 0.2], margin: 0.2}}\nvariants: {a: {}, b: {}}\n", "a");
  CHECK(along.space.camera.automatic);
  CHECK(along.space.camera.direction == Vec3(0, -1, 0.2));
  CHECK(along.space.camera.margin == 0.2);
  CHECK(along.render.panels.times == std::vector<double>{2.0});
}

TEST_CASE("3D render: faults at FILE:LINE:COL") {
  expectSceneError(kScene + "render: {sat: true}\n", 5, 15, {"2D scenes only", "omega_path"});
  expectSceneError(kScene + "render: {camera: {eye: [1, 0, 0]}}\n", 5, 18, {"both 'eye' and 'target'"});
  expectSceneError(kScene + "render: {camera: {center: [0, 0], height: 2}}\n", 5, 19, {"unknown key 'center'"});
  expectSceneError(kScene + "render: {camera: {direction: [0, 0, 1]}}\n", 5, 18, {"along 'up'"});
  expectSceneError(kScene + "render: {arrows: [{body: top, show: torque}]}\n", 5, 37, {"unknown show 'torque'", "omega_path"});
  expectSceneError(kScene + "render: {arrows: [{body: tip, show: omega}]}\n", 5, 26, {"no body named 'tip'"});
}

// The scene's render: block: documented defaults, every key read, and bad values reported at their
// FILE:LINE:COL with a message that says what to write instead.
#include <doctest/doctest.h>

#include "render/scene/scene_style.h"

#include <string>
#include <vector>

#include "support/drawn_scene.h"
#include "support/render_block.h"

using render::draw::Role;
using namespace render_block;

TEST_CASE("labels and contacts: auto (the default), or true and false as written") {
  const render::scene::RenderDef a = renderOf("render: {labels: auto, contacts: auto}\n");
  CHECK((a.labels && a.labelsAuto && a.contacts && a.contactsAuto));
  const render::scene::RenderDef on = renderOf("render: {labels: true, contacts: yes}\n");
  CHECK((on.labels && !on.labelsAuto && on.contacts && !on.contactsAuto));
  const render::scene::RenderDef off = renderOf("render: {labels: false, contacts: off}\n");
  CHECK((!off.labels && !off.labelsAuto && !off.contacts && !off.contactsAuto));
}

TEST_CASE("without a render block the documented defaults hold") {
  const render::scene::RenderDef r = renderOf("");
  CHECK(r.width == 1280);
  CHECK(r.height == 720);
  CHECK(r.fps == 60.0);
  CHECK(r.background == "#ffffff");
  // lines scale with the frame: 3 px at 1080p, 2 px at 720p
  CHECK(r.lineWidth == 0.0);
  CHECK(render::scene::lineWidthFor(r, 1080) == 3.0);
  CHECK(render::scene::lineWidthFor(r, 720) == 2.0);
  CHECK(render::scene::lineWidthFor(renderOf("render: {line_width: 1.5}"), 1080) == 1.5);
  CHECK(r.camera.automatic);
  CHECK(r.contacts);
  CHECK(r.contactsAuto);
  CHECK(r.contactHold == 0.5);
  CHECK(r.labels);
  CHECK(r.labelsAuto);
  CHECK(r.time);
  CHECK_FALSE(r.velocities);
  CHECK_FALSE(r.trails);
  CHECK_FALSE(r.sat);
  CHECK(r.strobe == 0);
  CHECK(r.springs);
  CHECK(r.colors[Role::Spring] == "#4d4d4d");
  CHECK(r.colors.palette.size() == 10);
}

TEST_CASE("every key is read") {
  const render::scene::RenderDef r = renderOf(
      "render:\n"
      "  size: [320, 180]\n"
      "  fps: 30\n"
      "  background: '#000000'\n"
      "  line_width: 1.5\n"
      "  font_size: 14\n"
      "  colors: {palette: ['#112233'], static: '#010203', contact: '#aabbcc', text: '#ffffff'}\n"
      "  camera: {center: [1, 2], height: 5}\n"
      "  contacts: false\n"
      "  contact_hold: 0.25\n"
      "  impulses: false\n"
      "  impulse_scale: 2\n"
      "  velocities: true\n"
      "  velocity_scale: 0.5\n"
      "  trails: true\n"
      "  sat: yes\n"
      "  strobe: 6\n"
      "  springs: false\n"
      "  labels: false\n"
      "  time: false\n");
  CHECK(r.width == 320);
  CHECK(r.height == 180);
  CHECK(r.fps == 30.0);
  CHECK(r.background == "#000000");
  CHECK(r.lineWidth == 1.5);
  CHECK(r.fontSize == 14.0);
  REQUIRE(r.colors.palette.size() == 1);
  CHECK(r.colors.palette[0] == "#112233");
  CHECK(r.colors[Role::StaticBody] == "#010203");
  CHECK(r.colors[Role::ContactPoint] == "#aabbcc");
  CHECK(r.colors[Role::Label] == "#ffffff");
  CHECK(r.colors[Role::Caption] == "#ffffff");        // both text roles take the key `text`
  CHECK(r.colors[Role::ContactNormal] == "#d55e00");  // untouched keys keep their defaults
  CHECK_FALSE(r.camera.automatic);
  CHECK(r.camera.center == sim::core::Vec2(1, 2));
  CHECK(r.camera.height == 5.0);
  CHECK_FALSE(r.contacts);
  CHECK(r.contactHold == 0.25);
  CHECK_FALSE(r.impulses);
  CHECK(r.impulseScale == 2.0);
  CHECK(r.velocities);
  CHECK(r.velocityScale == 0.5);
  CHECK(r.trails);
  CHECK(r.sat);
  CHECK(r.strobe == 6);
  CHECK_FALSE(r.springs);
  CHECK_FALSE(r.labels);
  CHECK_FALSE(r.time);
}

TEST_CASE("each body's color and label: its own, or the palette's and its name; a variant merges them by name") {
  const std::string text =
      "bodies:\n"
      "  - {name: bar, shape: {box: [1, 2]}, color: \"#3b6ea5\", label: the bar}\n"
      "  - {name: ground, shape: {circle: 2}, static: true}\n"
      "variants:\n"
      "  relabeled: {bodies: [{name: ground, label: floor}]}\n";
  const render::scene::RenderDef r = drawn_scene::load(text).render;
  REQUIRE(r.bodies.size() == 2);
  CHECK(r.bodies[0].color == "#3b6ea5");
  CHECK(r.bodies[0].label == "the bar");
  CHECK(r.bodies[1].color.empty());
  CHECK(r.bodies[1].label == "ground");
  CHECK(drawn_scene::load(text, "relabeled").render.bodies[1].label == "floor");
  try {
    (void)drawn_scene::load("bodies:\n  - {name: a, shape: {circle: 1}, color: blue}\n");
    FAIL_CHECK("the scene loaded; expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.line == 2);
    CHECK(e.message.find("\"#rrggbb\"") != std::string::npos);
  }
}

TEST_CASE("the camera is auto, auto with a margin, or fixed") {
  CHECK(renderOf("render: {camera: auto}").camera.automatic);
  const render::scene::RenderDef m = renderOf("render: {camera: {margin: 0.2}}");
  CHECK(m.camera.automatic);
  CHECK(m.camera.margin == 0.2);
}

TEST_CASE("variants can change the render block") {
  const std::string text = kBody +
                           "render: {size: [640, 360], trails: true}\n"
                           "variants:\n"
                           "  small: {render: {size: [320, 180]}}\n";
  const render::scene::RenderDef r = drawn_scene::load(text, "small").render;
  CHECK(r.width == 320);
  CHECK(r.trails);  // merged key by key
}

TEST_CASE("bad render values name the line and what to write") {
  expectError("render: {sise: [2, 2]}\n", 3, "did you mean 'size'");
  // far from every key of the block: the keys listed, no guess ('annotations' is not 'contacts')
  expectError("render: {annotations: true}\n", 3, "choose one of: size, fps,");
  expectError("render:\n  size: [321, 180]\n", 4, "even sides");
  expectError("render:\n  size: [320, 9000]\n", 4, "from 16 to 8192");
  expectError("render:\n  size: [320.5, 180]\n", 4, "whole number");
  expectError("render:\n  size: 320\n", 4, "[width, height]");
  expectError("render:\n  fps: 0\n", 4, "positive");
  expectError("render:\n  fps: 5000\n", 4, "at most 1000");
  expectError("render:\n  background: red\n", 4, "#rrggbb");
  expectError("render:\n  colors: {contact: '#12345'}\n", 4, "#rrggbb");
  expectError("render:\n  colors: {contacts: '#123456'}\n", 4, "did you mean 'contact'");
  expectError("render:\n  camera: fixed\n", 4, "'auto' or {center");
  expectError("render:\n  camera: {center: [0, 0]}\n", 4, "both 'center' and 'height'");
  expectError("render:\n  camera: {center: [0, 0], height: -1}\n", 4, "positive");
  expectError("render:\n  camera: {margin: 0.7}\n", 4, "below 0.5");
  expectError("render:\n  strobe: -1\n", 4, "whole number from 0 to 100");
  expectError("render:\n  trails: maybe\n", 4, "true or false");
  expectError("render:\n  labels: some\n", 4, "expected auto, true or false for 'labels'");
  expectError("render:\n  contacts: [1]\n", 4, "expected auto, true or false for 'contacts'");
  // a view whose pixels would not be finite numbers
  expectError("render:\n  camera: {center: [0, 0], height: 1e308}\n", 4, "at most 1e150 m");
  expectError("render:\n  camera: {center: [1e200, 0], height: 1}\n", 4, "at most 1e150 m");
  expectError("render:\n  contact_hold: -0.1\n", 4, "zero or a positive");
}

// the lecture overlays (render.overlays)
TEST_CASE("the lecture overlays are off by default") {
  const render::scene::OverlaysDef o = renderOf("").overlays;
  CHECK(o.arrows.empty());
  CHECK(o.forceScale == 0.0);
  CHECK(o.momentumScale == 0.0);
  CHECK_FALSE(o.impactValues);
  CHECK_FALSE(o.energy);
  CHECK_FALSE(o.momentum);
  CHECK_FALSE(o.satAxes);
}

TEST_CASE("arrows name their body and what to show; the other overlay keys are read") {
  const render::scene::OverlaysDef o = renderOf(
                                           "render:\n"
                                           "  arrows:\n"
                                           "    - {body: a, show: velocity, at: [0, 2], value: true}\n"
                                           "    - {body: a, show: torque, label: tau, color: '#00ff00'}\n"
                                           "  force_scale: 0.5\n"
                                           "  momentum_scale: 0.25\n"
                                           "  impact_values: true\n"
                                           "  energy: yes\n"
                                           "  momentum: true\n"
                                           "  sat_axes: true\n"
                                           "  colors: {force: '#010203', panel: '#eeeeee'}\n")
                                           .overlays;
  REQUIRE(o.arrows.size() == 2);
  CHECK(o.arrows[0].body == 0);
  CHECK(o.arrows[0].show == render::scene::ArrowDef::Show::Velocity);
  CHECK(o.arrows[0].at == sim::core::Vec2(0, 2));
  CHECK(o.arrows[0].value);
  CHECK(o.arrows[0].label.empty());
  CHECK(o.arrows[1].show == render::scene::ArrowDef::Show::Torque);
  CHECK(o.arrows[1].label == "tau");
  CHECK(o.arrows[1].color == "#00ff00");
  CHECK(o.arrows[1].at == sim::core::Vec2::Zero());
  CHECK(o.forceScale == 0.5);
  CHECK(o.momentumScale == 0.25);
  CHECK(o.impactValues);
  CHECK(o.energy);
  CHECK(o.momentum);
  CHECK(o.satAxes);
  CHECK(renderOf("render: {colors: {force: '#010203'}}\n").colors[Role::Force] == "#010203");
}

TEST_CASE("bad arrows name the line, the column and what to write") {
  expectError("render:\n  arrows: {body: a}\n", 4, "must be a list");
  expectError("render:\n  arrows:\n    - {show: velocity}\n", 5, "needs 'body'");
  expectError("render:\n  arrows:\n    - {body: b, show: velocity}\n", 5, "no body named 'b'; the bodies are: a");
  expectError("render:\n  arrows:\n    - {body: a}\n", 5, "needs 'show'");
  expectError("render:\n  arrows:\n    - {body: a, show: speed}\n", 5, "unknown show 'speed'; choose one of: velocity");
  expectError("render:\n  arrows:\n    - {body: a, show: omega, at: 1}\n", 5, "[x, y]");
  expectError("render:\n  arrows:\n    - {body: a, show: omega, colour: '#000000'}\n", 5, "did you mean 'color'");
  expectError("render:\n  arrows:\n    - {body: a, show: omega, color: blue}\n", 5, "#rrggbb");
  expectError("render:\n  force_scale: 0\n", 4, "positive");
  expectError("render:\n  energy: lots\n", 4, "true or false");
  try {
    (void)renderOf("render:\n  arrows:\n    - {body: b, show: velocity}\n");
    FAIL("an arrow naming an unknown body was accepted");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(std::string(e.what()).rfind("inline.yaml:5:14: no body named 'b'", 0) == 0);
  }
}

TEST_CASE("panels: the duration for two or more variants, none otherwise, or the times or impacts asked") {
  const std::string two = "duration: 3\nvariants: {a: {}, b: {}}\n";
  CHECK(renderOf("").panels.times.empty());
  CHECK_FALSE(renderOf("").panels.impacts);
  CHECK(renderOf("variants: {a: {}}\n").panels.times.empty());  // one variant: nothing to compare
  CHECK(renderOf(two).panels.times == std::vector<double>{3.0});
  CHECK(renderOf(two + "render: {panels: [0, 1.5, 3]}\n").panels.times == std::vector<double>{0.0, 1.5, 3.0});
  const render::scene::RenderDef impacts = renderOf(two + "render: {panels: impacts}\n");
  CHECK(impacts.panels.impacts);
  CHECK(impacts.panels.times.empty());
  CHECK(renderOf(two + "render: {panels: []}\n").panels.times.empty());  // explicitly none
  // a variant may change them, and its duration moves the default
  const std::string text = kBody + "duration: 3\nvariants: {a: {duration: 2}, b: {render: {panels: impacts}}}\n";
  CHECK(drawn_scene::load(text, "a").render.panels.times == std::vector<double>{2.0});
  CHECK(drawn_scene::load(text, "b").render.panels.impacts);
}

TEST_CASE("bad panels name the line and what to write") {
  const std::string two = "duration: 3\nvariants: {a: {}, b: {}}\n";  // lines 3-4; render: on line 5
  expectError("render:\n  panels: [1]\n", 4, "this scene has none");
  expectError(two + "render:\n  panels: [1, 4]\n", 6, "after the scene's duration (3 s)");
  expectError(two + "render:\n  panels: [-1]\n", 6, "zero or a positive");
  expectError(two + "render:\n  panels: 1.5\n", 6, "or 'impacts'");
  expectError(two + "render:\n  panels: impact\n", 6, "or 'impacts'");
}

// The middle level of the regression tests: the draw calls of a frame, without any GL. A change
// here and not in the state hash is a change in what is shown, not in the physics.
#include <doctest/doctest.h>

#include <cmath>
#include <map>

#include "render/draw/gl_canvas.h"
#include "render/frame/energy_panel.h"
#include "render/frame/scene_run.h"
#include "render/scene/scene_style.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"

using render::frame::FramePainter;

namespace {

const char* const kPoll = R"(
name: poll
duration: 2
sim: {integrator: rk4, dt: 0.001}
bodies:
  - {name: bar, shape: {box: [0.2, 4.0]}, mass: 3, inertia: 4, label: "bar"}
  - {name: floor, shape: {box: [6, 0.5]}, position: [0, -3], static: true}
events:
  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}
render: {velocities: true, trails: true, size: [320, 180]}
)";

render::draw::DrawList frameAt(const std::string& yaml, double t, int strobe = 0) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  render::frame::SceneRun run(def, camera, survey);
  return run.drawListAt(t, strobe);
}

}  // namespace

TEST_CASE("the poll at t = 0.75: static floor first, trail, bar, held impulse, velocity, labels, time") {
  // the bar turns at ω = −0.5 from t = 0.5 and moves at 1/3 m/s; the view is 6.25 m high, so the
  // automatic arrows are 6.25 / 6 = 1.04 m long for the largest impulse (1 N·s) and speed (1/3 m/s);
  // the impulse is drawn two line widths (2 px of 0.00868 m) to its left, beside any normal on its line
  CHECK(frameAt(kPoll, 0.75).toText() ==
        "polygon StaticBody#1 (-3,-3.25) (3,-3.25) (3,-2.75) (-3,-2.75)\n"
        "segment Trail#0 (0,0) (0.0523333,0)\n"
        "segment Trail#0 (0.0523333,0) (0.0833333,0)\n"
        "polygon Body#0 (-0.265236,-1.97193) (-0.0667964,-1.99686) (0.431903,1.97193) (0.233463,1.99686)\n"
        "arrow Impulse#0@0.5 (-1.04216,2.03474) -> (0,2.03474)\n"
        "arrow Velocity#0 (0.0833333,0) -> (1.1255,0)\n"
        "text Caption (-5.36714,2.31167) \"t = 0.750 s\"\n"
        "text Label#0 (0.0833333,0) \"bar\"\n"
        "text Label#1 (0,-3) \"floor\"\n");
}

TEST_CASE("a strobe frame has its ghosts, faint to less faint, behind the present bar") {
  const auto lines = frameAt(kPoll, 1.0, 3).lines();
  REQUIRE(lines.size() >= 5);
  CHECK(lines[0].rfind("polygon StaticBody#1", 0) == 0);
  // ghosts at t = 0, 1/3, 2/3 with opacities 0.15, 0.35, 0.55; the trail comes before them
  std::vector<std::string> ghosts;
  for (const std::string& l : lines)
    if (l.find("Body#0@") != std::string::npos) ghosts.push_back(l.substr(0, l.find(' ', 8)));
  CHECK(ghosts == std::vector<std::string>{"polygon Body#0@0.15", "polygon Body#0@0.35", "polygon Body#0@0.55"});
}

TEST_CASE("render switches turn parts of the frame off") {
  std::string quiet = kPoll;
  quiet.replace(quiet.find("render: {velocities: true, trails: true,"), 40,
                "render: {labels: false, time: false, impulses: false,");
  CHECK(frameAt(quiet, 0.75).toText() ==
        "polygon StaticBody#1 (-3,-3.25) (3,-3.25) (3,-2.75) (-3,-2.75)\n"
        "polygon Body#0 (-0.265236,-1.97193) (-0.0667964,-1.99686) (0.431903,1.97193) (0.233463,1.99686)\n");
}

TEST_CASE("the time caption has three decimals") {
  CHECK(FramePainter::timeText(0.5) == "t = 0.500 s");
  CHECK(FramePainter::timeText(12.3456) == "t = 12.346 s");
}

TEST_CASE("a spring is a zigzag from the body point to its anchor, with a dot at the anchor") {
  const std::string hanging =
      "duration: 1\n"
      "bodies:\n"
      "  - {name: bar, shape: {box: [0.1, 1]}, position: [0, -1.5]}\n"
      "forces:\n"
      "  - {type: spring, body: bar, point: [0, 0.5], anchor: [0, 0], stiffness: 10, rest_length: 1}\n"
      "render: {labels: false, time: false, size: [320, 180]}\n";
  const auto lines = frameAt(hanging, 0.0).lines();
  // the bar; a lead, 12 zigs, the way back to the axis and a lead (15 segments); the anchor
  REQUIRE(lines.size() == 1 + 15 + 1);
  CHECK(lines[1] == "segment Spring (0,-1) (0,-0.88)");
  CHECK(lines[15] == "segment Spring (0,-0.12) (0,0)");
  CHECK(lines[16] == "point StaticBody (0,0)");
}

TEST_CASE("the separating-axis overlay: reference edge, incident vertex and the separation, as the pair approaches") {
  // a box tilted by 0.3 rad above a static base whose top face is y = 0.5: its lowest corner is
  // 0.2 (cos 0.3 + sin 0.3) = 0.250171 below its center, 0.049829 above the face
  const std::string pair =
      "duration: 1\n"
      "sim: {collisions: none}\n"
      "bodies:\n"
      "  - {name: base, shape: {box: [2, 0.5]}, position: [0, 0.25], static: true}\n"
      "  - {name: box, shape: {box: [0.4, 0.4]}, position: [0, 0.8], angle: 0.3}\n"
      "render: {sat: true, labels: false, time: false, key: false, size: [320, 180], camera: {center: [0, 0.5], height: 2}}\n";
  const auto lines = frameAt(pair, 0.0).lines();
  REQUIRE(lines.size() == 5);
  CHECK(lines[2] == "segment ReferenceEdge#0 (1,0.5) (-1,0.5)");
  // the corner (−0.2, −0.2) of the box turned by 0.3 rad
  CHECK(lines[3] == "point IncidentVertex#1 (-0.131963,0.549829)");
  // a line of text (11 px of a 2 m view, 180 px high) below the edge's middle, inside the base
  CHECK(lines[4] == "text Label#0 (0,0.377778) \"separation 0.0498 m\"");
  // far apart (more than a tenth of the view): no overlay
  std::string apart = pair;
  apart.replace(apart.find("position: [0, 0.8]"), 18, "position: [0, 1.2]");
  CHECK(frameAt(apart, 0.0).lines().size() == 2);
}

TEST_CASE("contacts touching now are dots with normals into the moving body") {
  const std::string resting =
      "duration: 1\n"
      "world: {gravity: [0, -10]}\n"
      "sim: {collisions: sequential}\n"
      "bodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: box, shape: {box: [1, 1]}, position: [0, 0.5]}\n"
      "render: {labels: false, time: false, size: [320, 180], camera: {center: [0, 0.5], height: 2}}\n";
  std::vector<std::string> contacts;
  for (const std::string& l : frameAt(resting, 0.5).lines())
    if (l.find("Contact") != std::string::npos) contacts.push_back(l.substr(0, l.find(' ', 6)));
  // two manifold points, each a normal (pointing up, into the box) and a dot
  CHECK(contacts ==
        std::vector<std::string>{"arrow ContactNormal", "point ContactPoint", "arrow ContactNormal", "point ContactPoint"});
}

TEST_CASE("the caption: wrapped at the bottom left, at most two lines; the slow-motion note under the time") {
  // a 320 × 180 frame 1.8 m high: a pixel is 1 cm, the text 11 px with lines 14 px apart; without a
  // font the width is estimated at 6.6 px a code point, so a line (320 − 11 px) takes 46 of them
  const std::string text =
      "description: A ball rolls to the right at one metre per second, past the origin and on. Then it stops.\n"
      "duration: 1\n"
      "bodies:\n"
      "  - {name: ball, shape: {circle: 0.1}, velocity: [1, 0]}\n"
      "render: {caption: true, labels: false, size: [320, 180], camera: {center: [0, 0], height: 1.8},\n"
      "         slow_motion: {factor: 4, from: 0.2, to: 0.4}}\n";
  const render::scene::Scene def = drawn_scene::load(text);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  // the video's time map slows [0.2, 0.4) fourfold (time_map_test.cpp tests the map itself)
  run.showSlowMotion([](double t) { return t >= 0.2 && t < 0.4 ? 4.0 : 1.0; });
  const auto lines = run.drawListAt(0.3).lines();
  REQUIRE(lines.size() == 6);
  CHECK(lines[2] == "text Caption (-1.545,0.845) \"t = 0.300 s\"");
  CHECK(lines[3] == "text Caption (-1.545,0.705) \"slow motion ×1/4\"");
  // line tops 28 and 14 px above the bottom inset (174.5 px from the top)
  CHECK(lines[4] == "text Caption (-1.545,-0.565) \"A ball rolls to the right at one metre per\"");
  CHECK(lines[5] == "text Caption (-1.545,-0.705) \"second, past the origin and on.\"");
  // outside the window, and in snapshots (no map), no note
  CHECK(run.drawListAt(0.5).lines().size() == 5);
  render::frame::SceneRun snapshot(def, render::frame::cameraFor(def, survey), survey);
  CHECK(snapshot.drawListAt(0.3).lines().size() == 5);
}

TEST_CASE("the slow-motion note names the factor") {
  CHECK(FramePainter::slowMotionText(4.0) == "slow motion ×1/4");
  CHECK(FramePainter::slowMotionText(2.5) == "slow motion ×1/2.5");
}

TEST_CASE("with a caption the automatic camera fits the bodies above its band, and without one as before") {
  const std::string scene =
      "description: A ball. It rolls.\n"
      "bodies:\n"
      "  - {name: ball, shape: {circle: 1}}\n"
      "render: {size: [320, 180], camera: {margin: 0}}\n";
  const render::scene::Scene plain = drawn_scene::load(scene);
  const render::frame::RunSurvey survey = render::frame::surveyRun(plain);
  const render::draw::Camera before = render::frame::cameraFor(plain, survey);
  CHECK(before.worldHeight() == doctest::Approx(2.0));
  CHECK(before.toPixel({0, -1}).y() == doctest::Approx(180.0));
  std::string captioned = scene;
  captioned.replace(captioned.find("margin: 0}"), 10, "margin: 0}, caption: true");
  const render::draw::Camera after = render::frame::cameraFor(drawn_scene::load(captioned), survey);
  // 11 px text: a band of 5.5 + 2 × 14 px; the ball fills the 147 px above it (whole pixels)
  CHECK(after.toPixel({0, 1}).y() == doctest::Approx(0.0));
  CHECK(after.toPixel({0, -1}).y() == doctest::Approx(147.0));
}

TEST_CASE("with an energy panel the automatic camera fits the bodies left of its band") {
  const std::string scene =
      "bodies:\n"
      "  - {name: ball, shape: {circle: 1}, velocity: [0, 0.001]}\n"
      "render: {size: [640, 180], camera: {margin: 0}, energy: true}\n";
  const render::scene::Scene def = drawn_scene::load(scene);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const double band = render::frame::EnergyPanel::bandPx(def, survey, 180);
  // a real panel, narrower than the frame
  REQUIRE(band > 50.0);
  REQUIRE(band < 640.0 - 180.0);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  // the ball is fitted by its height (the free part is wider than tall), centered in the free part;
  // its rightmost point stays left of the panel
  CHECK(camera.worldHeight() == doctest::Approx(2.0).epsilon(1e-3));
  CHECK(camera.toPixel({0, 0}).x() == doctest::Approx(0.5 * std::lround(640 - band)).epsilon(1e-9));
  CHECK(camera.toPixel({1, 0}).x() < 640.0 - band);
  // without the panel the ball is in the middle of the frame
  render::scene::Scene plain = def;
  plain.render.overlays.energy = false;
  CHECK(render::frame::cameraFor(plain, survey).toPixel({0, 0}).x() == doctest::Approx(320.0));
}

TEST_CASE("with an energy panel wider than the room beside it, the automatic camera fits the bodies under it") {
  // a ball rolling 10 m along a line, in a frame too narrow for the bodies beside the panel
  const std::string scene =
      "duration: 1\n"
      "bodies:\n"
      "  - {name: ball, shape: {circle: 0.5}, velocity: [10, 0]}\n"
      "render: {size: [320, 360], camera: {margin: 0}, energy: true}\n";
  const render::scene::Scene def = drawn_scene::load(scene);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const double band = render::frame::EnergyPanel::bandPx(def, survey, 360);
  const double top = render::frame::EnergyPanel::topBandPx(def, survey, 320, 360);
  REQUIRE(band > 160.0);
  REQUIRE(top > 0.0);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  // the run's 11 m span the whole width, and the ball's top stays under the panel's band
  CHECK(camera.worldWidth() == doctest::Approx(11.0).epsilon(1e-3));
  CHECK(camera.toPixel({0, 0.5}).y() >= top - 1e-9);
  CHECK(camera.toPixel({-0.5, 0}).x() == doctest::Approx(0.0).epsilon(1e-9));
}

namespace {

// Box2D's pyramid (render/bench/stack_layouts.h): rows of 1 m boxes 1.125 m apart on a ground box,
// `base` boxes in the bottom row, base·(base + 1)/2 in all, resting on each other, soft_step
std::string pyramid(int base, const std::string& render = "") {
  std::string yaml =
      "name: pyramid\nduration: 0.5\nworld: {gravity: [0, -10], friction: 0.6}\n"
      "sim: {collisions: soft_step, dt: 0.016666666666666667, max_bodies: 100000}\n" +
      render + "bodies:\n  - {name: ground, shape: {box: [80, 1]}, position: [0, -0.5], static: true}\n";
  for (int r = 0; r < base; ++r)
    for (int j = 0; j < base - r; ++j)
      yaml += "  - {name: b" + std::to_string(r) + "_" + std::to_string(j) + ", shape: {box: [1, 1]}, position: [" +
              std::to_string(-7.0 + 0.5625 * r + 1.125 * j) + ", " + std::to_string(0.5 + r) + "]}\n";
  return yaml;
}

struct PyramidFrame {
  render::draw::DrawList calls;
  std::vector<render::frame::PlacedText> placed;
};

PyramidFrame pyramidFrame(const std::string& yaml, double t) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  PyramidFrame f;
  f.calls = run.drawListAt(t, 0, &f.placed);
  return f;
}

}  // namespace

TEST_CASE("the 210-box pyramid at the defaults: at most one label per body, no leader line, contacts as dots") {
  const PyramidFrame f = pyramidFrame(pyramid(20), 0.5);
  std::map<int, int> labels;
  for (const render::frame::PlacedText& t : f.placed) {
    CHECK_FALSE(t.leader);
    if (t.pen.role == render::draw::Role::Label) ++labels[t.pen.body];
  }
  for (const auto& [body, count] : labels) CHECK(count <= 1);
  size_t points = 0, normals = 0;
  for (const render::draw::DrawList::Call& c : f.calls.calls()) {
    // a leader line is a segment in the label's role
    CHECK_FALSE((c.kind == render::draw::DrawList::Kind::Segment && c.style.role == render::draw::Role::Label));
    points += c.kind == render::draw::DrawList::Kind::Point && c.style.role == render::draw::Role::ContactPoint;
    normals += c.style.role == render::draw::Role::ContactNormal;
  }
  // hundreds of contact points on screen: their dots, without normals
  CHECK(points >= 200);
  CHECK(normals == 0);
}

TEST_CASE("labels: true and contacts: true keep every label and every normal, however many bodies") {
  const PyramidFrame f = pyramidFrame(pyramid(20, "render: {labels: true, contacts: true}\n"), 0.5);
  size_t labels = 0, normals = 0, points = 0;
  for (const render::frame::PlacedText& t : f.placed) labels += t.pen.role == render::draw::Role::Label;
  for (const render::draw::DrawList::Call& c : f.calls.calls()) {
    normals += c.style.role == render::draw::Role::ContactNormal;
    points += c.kind == render::draw::DrawList::Kind::Point && c.style.role == render::draw::Role::ContactPoint;
  }
  CHECK(normals == points);
  CHECK(points >= 200);
  // every label was tried: placed or dropped, none left out for not fitting
  CHECK(labels > 0);
}

TEST_CASE("labels: auto in a larger scene writes a label only where it fits inside its body") {
  // 25 bodies: big boxes with short names, and small ones that cannot hold theirs
  std::string yaml =
      "name: fit\nduration: 0.1\nworld: {gravity: [0, 0]}\nsim: {collisions: none}\n"
      "render: {size: [640, 360], camera: {center: [0, 0], height: 30}}\nbodies:\n";
  for (int i = 0; i < 5; ++i)
    yaml += "  - {name: B" + std::to_string(i) + ", shape: {box: [4, 4]}, position: [" + std::to_string(-20 + 9 * i) + ", 8]}\n";
  for (int i = 0; i < 20; ++i)
    yaml += "  - {name: small_box_" + std::to_string(i) + ", shape: {box: [0.5, 0.5]}, position: [" +
            std::to_string(-20 + 2 * i) + ", -5]}\n";
  const PyramidFrame f = pyramidFrame(yaml, 0.0);
  std::vector<std::string> labels;
  for (const render::frame::PlacedText& t : f.placed)
    if (t.pen.role == render::draw::Role::Label) labels.push_back(t.text);
  CHECK(labels == std::vector<std::string>{"B0", "B1", "B2", "B3", "B4"});
  // a scene of at most 20 bodies keeps all its labels
  std::string few =
      "name: few\nduration: 0.1\nworld: {gravity: [0, 0]}\nsim: {collisions: none}\n"
      "render: {size: [640, 360], camera: {center: [0, 0], height: 30}}\nbodies:\n";
  for (int i = 0; i < 3; ++i)
    few += "  - {name: small_box_" + std::to_string(i) + ", shape: {box: [0.5, 0.5]}, position: [" + std::to_string(-10 + 8 * i) +
           ", 0]}\n";
  size_t shown = 0;
  for (const render::frame::PlacedText& t : pyramidFrame(few, 0.0).placed) shown += t.pen.role == render::draw::Role::Label;
  CHECK(shown == 3);
}

TEST_CASE("a frame's GL draw calls do not grow with the bodies: the same at 55 and at 210 boxes") {
  const auto calls = [](int base) {
    const render::scene::Scene def = drawn_scene::load(pyramid(base, "render: {size: [320, 180]}\n"));
    const render::frame::RunSurvey survey = render::frame::surveyRun(def);
    const render::draw::Camera camera = render::frame::cameraFor(def, survey);
    render::draw::GlContext gl(320, 180);
    render::draw::TextRenderer text;
    const render::draw::Style style = render::scene::makeStyle(def, 180);
    render::draw::GlCanvas canvas(gl, text, style);
    FramePainter painter(def, camera, survey);
    sim::world::World world = sim::scene::buildWorld(def.model);
    render::frame::History history(world, painter.historyOptions());
    world.advanceTo(0.5, &history);
    canvas.begin(camera);
    painter.paint(world, history, {}, canvas);
    canvas.finish();
    return canvas.drawCalls();
  };
  const int few = calls(10), many = calls(20);
  CHECK(few == many);
  // the ground (its fill, its hatching, its outline) and one batch of everything opaque
  CHECK(many <= 6);
}

namespace {

using sim::core::Vec2;

// the contact dots a painted frame asks for: how many, and the radius it gives the canvas for them
struct DotCount final : render::draw::Canvas {
  size_t points = 0;
  std::vector<double> radii;
  void polygon(const std::vector<Vec2>&, const render::draw::Pen&) override {}
  void circle(const Vec2&, double, const render::draw::Pen&) override {}
  void halfPlane(const Vec2&, const Vec2&, const render::draw::Pen&) override {}
  void segment(const Vec2&, const Vec2&, const render::draw::Pen&) override {}
  void point(const Vec2&, const render::draw::Pen& p) override { points += p.role == render::draw::Role::ContactPoint; }
  void arrow(const Vec2&, const Vec2&, const render::draw::Pen&) override {}
  void text(const Vec2&, const std::string&, const render::draw::Pen&) override {}
  void label(const Vec2&, const Vec2&, const std::string&, const render::draw::Pen&) override {}
  void manyPoints(double radiusPx) override { radii.push_back(radiusPx); }
};

struct DenseDots {
  DotCount dots;
  double boxPx;  // a 1 m box's width on the frame
};

DenseDots denseDots(const std::string& yaml) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  FramePainter painter(def, camera, survey);
  sim::world::World world = sim::scene::buildWorld(def.model);
  render::frame::History history(world, painter.historyOptions());
  world.advanceTo(0.5, &history);
  DenseDots d{{}, 1.0 / camera.pixelSize()};
  painter.paint(world, history, {}, d.dots);
  return d;
}

}  // namespace

TEST_CASE("many contact dots are scaled to the boxes they sit on, and left out where under a pixel or two") {
  // 1280x720: 1 m boxes about 13 px across, so dots an eighth of that, not the usual 4.4 px
  const DenseDots wide = denseDots(pyramid(20, "render: {size: [1280, 720]}\n"));
  CAPTURE(wide.boxPx);
  CHECK(wide.dots.points >= 200);
  REQUIRE(wide.dots.radii.size() == 2);
  CHECK(wide.dots.radii[0] == doctest::Approx(0.125 * wide.boxPx).epsilon(0.01));
  CHECK(wide.dots.radii[0] < 2.2 * 2.0);
  CHECK(wide.dots.radii[1] == 0.0);
  // 320x180: boxes about 3 px across, whose dots would be a blur over each: none drawn
  const DenseDots small = denseDots(pyramid(20, "render: {size: [320, 180]}\n"));
  CAPTURE(small.boxPx);
  CHECK(0.125 * small.boxPx < 0.75);
  CHECK(small.dots.points == 0);
  // few contacts keep the usual dots, with no radius told
  const DenseDots few = denseDots(pyramid(3, "render: {size: [1280, 720]}\n"));
  CHECK(few.dots.points > 0);
  CHECK(few.dots.radii.empty());
}

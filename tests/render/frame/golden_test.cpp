// The third level of the regression tests: frames compared with the PNGs in tests/golden/, with a
// tolerance for rasterizer round-off (see tests/golden/README.md for the thresholds and for when to
// regenerate them with `make golden`). On a failure the frame drawn and a diff image are written
// under out/golden-diff/ and named in the message. Also: the same scene rendered twice gives
// byte-identical PNGs.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "render/draw/gl_canvas.h"
#include "render/draw/png_io.h"
#include "render/frame/panels.h"
#include "render/video/render_plan.h"
#include "render/frame/scene_run.h"
#include "render/scene/scene_style.h"
#include "render/video/time_map.h"
#include "sim/world/diagnostics.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"
#include "support/golden_compare.h"

namespace fs = std::filesystem;
using golden::checkGolden;
using render::draw::Image;
using render::draw::Role;

namespace {

// an inline scene ready to paint at its own size, through its own camera
struct InlineRun {
  explicit InlineRun(const std::string& yaml, const std::string& variant = "")
      : def(drawn_scene::load(yaml, variant)),
        survey(render::frame::surveyRun(def)),
        gl(def.render.width, def.render.height),
        run(def, render::frame::cameraFor(def, survey), survey, &gl, &text) {}
  const render::scene::Scene def;
  const render::frame::RunSurvey survey;
  render::draw::GlContext gl;
  render::draw::TextRenderer text;
  render::frame::SceneRun run;
};

// the frame of an inline scene at time t
Image frame(const std::string& yaml, double t, const std::string& variant = "", int strobe = 0) {
  return InlineRun(yaml, variant).run.frameAt(t, strobe);
}

const char* const kBodies = R"(
name: golden_bodies
sim: {collisions: none}
bodies:
  - {name: box, shape: {box: [1.2, 0.8]}, position: [-2, 0.6], angle: 0.3, label: "box"}
  - {name: tri, shape: {polygon: [[0, 0], [1.2, 0], [0.3, 1]]}, position: [0, 0.7], label: "triangle"}
  - {name: wheel, shape: {circle: 0.5}, position: [2, 0.6], angle: 0.8, label: "ω wheel"}
  - {name: ledge, shape: {box: [2, 0.3]}, position: [0, -0.4], static: true, label: "ledge"}
  - {name: floor, shape: {plane: {point: [0, -1.1], normal: [0.1, 1]}}}
render: {size: [320, 180], camera: {center: [0, 0.2], height: 3.6}, line_width: 1.5}
)";

// the notes' "three collisions" case A: the ball meets the block's face at t = 0.75
const char* const kImpact = R"(
name: golden_impact
duration: 1.5
world: {restitution: 1}
sim: {collisions: event}
bodies:
  - {name: ball, shape: {circle: 0.25}, mass: 1, inertia: 0.2, velocity: [1, 0], color: "#c8553d"}
  - {name: block, shape: {box: [1, 1]}, mass: 1, inertia: 0.2, position: [1.5, 0.3], color: "#3b6ea5"}
render: {size: [320, 180], camera: {center: [1.1, 0.2], height: 2.2}, line_width: 1.5, contact_hold: 0.5}
)";

const char* const kPoll = R"(
name: golden_poll
duration: 2
sim: {integrator: rk4, dt: 0.001}
bodies:
  - {name: bar, shape: {box: [0.2, 4.0]}, mass: 3, inertia: 4, color: "#3b6ea5"}
events:
  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}
variants:
  center: {events: [{time: 0.5, body: bar, impulse: [1, 0], point: [0, 0]}]}
  end: {}
  # the lecture's text: a title card, a caption from the description, slow motion
  lecture:
    description: >
      A bar at rest is struck at its end by a horizontal impulse. It turns about its center of mass
      while the center moves on as if the impulse had struck it there.
    render: {title: "Impulses", title_card: 2, caption: true, slow_motion: {factor: 4, from: 0.4, to: 0.8}}
render: {size: [320, 180], line_width: 1.5}
)";

const char* const kProjectile = R"(
name: golden_projectile
duration: 1.2
world: {gravity: [0, -9.81]}
bodies:
  - {name: box, shape: {box: [0.4, 0.2]}, velocity: [3, 5], angular_velocity: 6, label: "box"}
render: {size: [320, 180], line_width: 1.5, trails: true, velocities: true}
)";

// the lecture overlays: the poll's bar after its blow, with labeled teaching arrows
const char* const kArrows = R"(
name: golden_arrows
duration: 2
sim: {integrator: rk4, dt: 0.001}
bodies:
  - {name: bar, shape: {box: [0.2, 4.0]}, mass: 3, inertia: 4, color: "#3b6ea5", label: ""}
events:
  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}
render:
  size: [320, 180]
  line_width: 1.5
  camera: {center: [0.9, 0], height: 5.2}
  velocity_scale: 1.5
  arrows:
    - {body: bar, show: velocity, at: [0, 2], value: true}
    - {body: bar, show: offset, at: [0, 2]}
    - {body: bar, show: omega, value: true}
    - {body: bar, show: path, at: [0, -2]}
)";

// the energy panel and momenta of a ball bouncing on a floor
const char* const kEnergy = R"(
name: golden_energy
duration: 1.5
world: {gravity: [0, -9.81], restitution: 0.7}
bodies:
  - {name: ball, shape: {circle: 0.3}, position: [-1, 1.5], velocity: [1, 0], angular_velocity: -2, label: ""}
  - {name: floor, shape: {box: [6, 0.4]}, position: [0, -0.2], static: true, label: ""}
render:
  size: [320, 180]
  line_width: 1.5
  font_size: 8
  camera: {center: [0.6, 1.1], height: 3.0}
  energy: true
  momentum: true
  impact_values: true
)";

}  // namespace

TEST_CASE("golden: labeled teaching arrows: v + ω × r′ at the bar's top, r′, ω, a point's path") {
  checkGolden("teaching_arrows", frame(kArrows, 1.5));
}

TEST_CASE("golden: the energy panel and momenta, an impact labeled with its values") {
  checkGolden("energy_panel", frame(kEnergy, 0.62));
}

TEST_CASE("golden: bodies of every shape, static ones hatched, a half-plane, labels, the time") {
  checkGolden("bodies", frame(kBodies, 0.0));
}

// Box2D's pyramid, base 20 (210 boxes of 1 m) resting, soft_step: a frame of about 800 contact points
std::string densePyramid() {
  std::string yaml =
      "name: golden_pyramid\nduration: 0.5\nworld: {gravity: [0, -10], friction: 0.6}\n"
      "sim: {collisions: soft_step, dt: 0.016666666666666667}\nrender: {size: [640, 360]}\n"
      "bodies:\n  - {name: ground, shape: {box: [40, 1]}, position: [3.7, -0.5], static: true}\n";
  for (int r = 0; r < 20; ++r)
    for (int j = 0; j < 20 - r; ++j)
      yaml += "  - {name: b" + std::to_string(r) + "_" + std::to_string(j) + ", shape: {box: [1, 1]}, position: [" +
              std::to_string(-7.0 + 0.5625 * r + 1.125 * j) + ", " + std::to_string(0.5 + r) + "]}\n";
  return yaml;
}

TEST_CASE("golden: a dense frame, its contacts as dots scaled to the boxes, without normals or labels") {
  checkGolden("dense_pyramid", frame(densePyramid(), 0.5));
}

TEST_CASE("golden: an impact's contact point, normal and impulses") { checkGolden("impact", frame(kImpact, 0.75)); }

TEST_CASE("golden: the impact held on screen, half faded") { checkGolden("impact_fading", frame(kImpact, 1.0)); }

TEST_CASE("golden: an event's impulse arrow, held after it strikes") { checkGolden("event_impulse", frame(kPoll, 0.6, "end")); }

TEST_CASE("golden: trails and velocity arrows") { checkGolden("trails_velocities", frame(kProjectile, 1.0)); }

TEST_CASE("golden: a strobe image") { checkGolden("strobe", frame(kProjectile, 1.2, "", 8)); }

TEST_CASE("golden: the poll panel sheet, A, B and C at the same instant, as `snapshot --panels` plans it") {
  // a 320 × 180 sheet: three panels as 2 × 2, their titles and the caption once under them
  const auto load = [](const std::string& v) { return drawn_scene::load(kPoll, v); };
  const render::video::RenderPlan plan = render::video::planStills(
      load, {.file = "poll.yaml", .times = {1.5}, .panels = true, .size = render::video::FrameSize{320, 180}});
  const render::video::Stills& stills = *plan.stills;
  render::draw::GlContext gl(stills.width, stills.height);
  render::draw::TextRenderer text;
  std::vector<Image> frames;
  for (size_t i = 0; i < stills.scenes.size(); ++i) {
    render::frame::SceneRun run(stills.scenes[i], stills.camera, stills.surveys[i], &gl, &text);
    frames.push_back(run.frameAt(1.5));
  }
  const render::draw::Style style = render::scene::makeStyle(stills.scenes[0], stills.height);
  const Image sheet = render::frame::composePanels(frames, stills.grid, stills.shots[0].titles, stills.caption, style, text);
  CHECK(sheet.width == 320);
  CHECK(sheet.height == 180);
  checkGolden("poll_panel", sheet);
}

TEST_CASE("golden: the separating-axis overlay, drawn from a hand-written draw list") {
  // two boxes, A resting 0.05 m into B: B's top face is the reference edge, A's lower-left corner
  // the incident vertex; two contact points with their normals (from B to A)
  const render::scene::Scene def = drawn_scene::load(kBodies);
  const render::draw::Style style = render::scene::makeStyle(def, 180);
  render::draw::GlContext gl(320, 180);
  render::draw::TextRenderer text;
  render::draw::GlCanvas canvas(gl, text, style);
  canvas.begin(render::draw::Camera({0, 0}, 2.4, 320, 180));
  canvas.polygon({{-1.5, -0.9}, {1.5, -0.9}, {1.5, -0.1}, {-1.5, -0.1}}, {Role::Body, 1, 1.0});
  canvas.polygon({{-0.6, -0.15}, {0.5, -0.05}, {0.45, 0.75}, {-0.65, 0.65}}, {Role::Body, 0, 1.0});
  canvas.segment({-1.5, -0.1}, {1.5, -0.1}, {Role::ReferenceEdge, 1, 1.0});
  canvas.point({-0.6, -0.15}, {Role::IncidentVertex, 0, 1.0});
  for (const sim::core::Vec2& p : {sim::core::Vec2(-0.6, -0.125), sim::core::Vec2(0.5, -0.075)}) {
    canvas.arrow(p, p + sim::core::Vec2(0, 0.5), {Role::ContactNormal, -1, 1.0});
    canvas.point(p, {Role::ContactPoint, -1, 1.0});
  }
  canvas.text({0.9, 0.5}, "separation −0.05 m", {Role::Label, -1, 1.0});
  canvas.text({-1.9, 1.1}, "t = 0.000 s", {Role::Caption, -1, 1.0});
  checkGolden("sat_overlay", canvas.finish());
}

TEST_CASE("golden: the separating-axis overlay of a box approaching a static base, from the world") {
  checkGolden("sat_scene", frame(R"(
name: golden_sat
duration: 1
sim: {collisions: none}
bodies:
  - {name: base, shape: {box: [2, 0.5]}, position: [0, 0.25], static: true}
  - {name: box, shape: {box: [0.6, 0.4]}, position: [0.1, 0.85], angle: 0.3}
render: {sat: true, size: [320, 180], camera: {center: [0, 0.5], height: 1.6}, line_width: 1.5}
)",
                                 0.0));
}

TEST_CASE("golden: a title card shows only the card: the title and the description, no bodies, clock or caption") {
  InlineRun lecture(kPoll, "lecture");
  const Image card = lecture.run.titleCard();
  checkGolden("title_card", card);
  // the text is gray on white: a pixel of the blue bar's color would be the run showing through
  long colored = 0;
  for (int y = 0; y < card.height; ++y)
    for (int x = 0; x < card.width; ++x) {
      const uint8_t* p = card.pixel(x, y);
      colored += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 8;
    }
  CHECK(colored == 0);
  // where the clock and the caption would be (the top and bottom bands), only the background
  long marked = 0;
  for (int y = 0; y < card.height; ++y)
    for (int x = 0; x < card.width; ++x)
      if (y < card.height / 8 || y >= card.height - card.height / 8) marked += card.pixel(x, y)[0] != 255;
  CHECK(marked == 0);
}

TEST_CASE("golden: a caption of two lines and the slow-motion note of a video frame") {
  InlineRun lecture(kPoll, "lecture");
  const render::video::TimeMap map =
      render::video::timeMapFor(lecture.def.render, lecture.survey.impactTimes, lecture.def.model.duration);
  lecture.run.showSlowMotion([&map](double t) { return map.factorAt(t); });
  checkGolden("caption", lecture.run.frameAt(0.6));
}

TEST_CASE("the same scene rendered twice gives byte-identical PNGs and the same state hash") {
  const render::scene::Scene def = drawn_scene::load(kImpact);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::draw::GlContext gl(def.render.width, def.render.height);
  render::draw::TextRenderer text;
  std::vector<std::vector<uint8_t>> pngs;
  std::vector<unsigned long long> hashes;
  for (int run = 0; run < 2; ++run) {
    render::frame::SceneRun r(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
    pngs.push_back(render::draw::encodePng(r.frameAt(0.75)));
    pngs.push_back(render::draw::encodePng(r.frameAt(1.25)));
    hashes.push_back(sim::world::stateHash(r.world()));
  }
  CHECK(pngs[0] == pngs[2]);
  CHECK(pngs[1] == pngs[3]);
  CHECK(hashes[0] == hashes[1]);
}

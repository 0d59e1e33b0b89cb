// The middle level of the regression tests: the draw calls of a frame, without any GL. A change
// here and not in the state hash is a change in what is shown, not in the physics.
#include <doctest/doctest.h>

#include "scene_run.h"
#include "scene_yaml.h"

using render::FramePainter;

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

render::DrawList frameAt(const std::string& yaml, double t, int strobe = 0) {
  const sim::SceneDef def = sim::loadSceneText(yaml, "inline.yaml");
  const render::RunSurvey survey = render::surveyRun(def);
  const render::Camera camera = render::Camera::fit(survey.bounds, def.render.camera.margin, 320, 180);
  render::SceneRun run(def, camera, survey);
  return run.drawListAt(t, strobe);
}

}  // namespace

TEST_CASE("the poll at t = 0.75: static floor first, trail, bar, held impulse, velocity, labels, time") {
  // the bar turns at ω = −0.5 from t = 0.5 and moves at 1/3 m/s; the view is 6.25 m high, so the
  // automatic arrows are 6.25 / 6 = 1.04 m long for the largest impulse (1 N·s) and speed (1/3 m/s)
  CHECK(frameAt(kPoll, 0.75).toText() ==
        "polygon StaticBody#1 (-3,-3.25) (3,-3.25) (3,-2.75) (-3,-2.75)\n"
        "segment Trail#0 (0,0) (0.0523333,0)\n"
        "segment Trail#0 (0.0523333,0) (0.0833333,0)\n"
        "polygon Body#0 (-0.265236,-1.97193) (-0.0667964,-1.99686) (0.431903,1.97193) (0.233463,1.99686)\n"
        "arrow Impulse#0@0.5 (-1.04216,2) -> (0,2)\n"
        "arrow Velocity#0 (0.0833333,0) -> (1.1255,0)\n"
        "text Label#0 (0.0833333,0) \"bar\"\n"
        "text Label#1 (0,-3) \"floor\"\n"
        "text Caption (-5.36714,2.31167) \"t = 0.750 s\"\n");
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

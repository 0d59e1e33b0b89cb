// The key to the overlays not labelled where they are drawn (overlay_key.cpp): the reference edge and
// incident vertex of the separating-axis overlay, the contact normal against the impulse; each row a
// sample of the mark and its name, in the top-left corner under the clock; only what the frame drew,
// never where impact_values writes n̂ and j, and never with `key: false`.
#include "render/frame/overlay_key.h"

#include <doctest/doctest.h>

#include "render/frame/scene_run.h"
#include "support/drawn_scene.h"

using render::draw::DrawList;
using render::draw::Role;

namespace {

std::string frameAt(const std::string& yaml, double t) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  return run.drawListAt(t).toText();
}

// two boxes closing in (a's right face reaches b's nearest corner at t = 1.75), the separating-axis
// overlay on
const std::string kBoxes = R"(
duration: 2
sim: {collisions: event}
bodies:
  - {name: a, shape: {box: [1, 1]}, position: [-1, 0], velocity: [0.5, 0]}
  - {name: b, shape: {box: [1, 1]}, position: [1, 0.2], angle: 0.3}
render: {size: [640, 360], sat: true}
)";

}  // namespace

TEST_CASE("the separating-axis overlay's key: its reference edge and incident vertex, under the clock") {
  const std::string frame = frameAt(kBoxes, 1.6);
  CHECK(frame.find("\"reference edge\"") != std::string::npos);
  CHECK(frame.find("\"incident vertex\"") != std::string::npos);
  // the samples as the overlay draws them
  CHECK(frame.find("segment ReferenceEdge (") != std::string::npos);
  CHECK(frame.find("point IncidentVertex (") != std::string::npos);
  // none of the contacts' rows: no impact yet
  CHECK(frame.find("impulse j") == std::string::npos);
  std::string off = kBoxes;
  off.replace(off.find("sat: true"), 9, "sat: true, key: false");
  CHECK(frameAt(off, 1.6).find("reference edge") == std::string::npos);
}

TEST_CASE("an impact's normal and impulse keyed, unless impact_values writes n̂ and j beside them") {
  const std::string bounce = drawn_scene::bounce("1", "render: {size: [640, 360]}\n");
  const std::string frame = frameAt(bounce, 0.6);
  CHECK(frame.find("\"contact normal n̂\"") != std::string::npos);
  CHECK(frame.find("\"impulse j\"") != std::string::npos);
  CHECK(frameAt(bounce, 0.25).find("impulse j") == std::string::npos);
  const std::string labelled = drawn_scene::bounce("1", "render: {size: [640, 360], impact_values: true}\n");
  CHECK(frameAt(labelled, 0.6).find("impulse j") == std::string::npos);
}

TEST_CASE("the key starts under the clock, the slow-motion note and the overlay's legend") {
  render::scene::RenderDef r;
  CHECK(render::frame::keyFirstRow(r) == 1);
  r.slowMotion.push_back({4.0, 0.2, 0.0, 0.0});
  CHECK(render::frame::keyFirstRow(r) == 2);
  r.time = false;
  r.slowMotion.clear();
  CHECK(render::frame::keyFirstRow(r) == 0);
}

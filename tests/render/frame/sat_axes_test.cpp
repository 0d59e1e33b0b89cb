// sat_axes: every edge of both polygons is a candidate axis, labeled with its separation.
#include <doctest/doctest.h>

#include "render/draw/draw_list.h"
#include "render/frame/sat_axes.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"

using render::draw::DrawList;

namespace {

// a unit box 0.1 m above a static 2 × 1 base
const sim::scene::SceneDef kPair = sim::yaml::loadSceneText(R"(
bodies:
  - {name: base, shape: {box: [2, 1]}, static: true}
  - {name: box, shape: {box: [1, 1]}, position: [0, 1.1]}
)", "inline.yaml");

}  // namespace

TEST_CASE("an edge's separation is the least distance of the other polygon's vertices past it") {
  const sim::world::World w = sim::scene::buildWorld(kPair);
  // the base's edges from (−1, −0.5) counter-clockwise: bottom, right, top, left
  CHECK(render::frame::edgeSeparation(w.bodies[0], 0, w.bodies[1]) == doctest::Approx(-2.1));
  CHECK(render::frame::edgeSeparation(w.bodies[0], 1, w.bodies[1]) == doctest::Approx(-1.5));
  CHECK(render::frame::edgeSeparation(w.bodies[0], 2, w.bodies[1]) == doctest::Approx(0.1));
  CHECK(render::frame::edgeSeparation(w.bodies[1], 0, w.bodies[0]) == doctest::Approx(0.1));
}

TEST_CASE("every edge but the reference one gets its label, inside its polygon") {
  const sim::world::World w = sim::scene::buildWorld(kPair);
  DrawList list;
  render::frame::describeCandidateAxes(w, 0, 1, 2, 0.05, list);
  std::vector<std::string> texts;
  for (const auto& c : list.calls()) texts.push_back(c.text);
  CHECK(texts == std::vector<std::string>{"-2.1 m", "-1.5 m", "-1.5 m", "0.1 m", "-1.5 m", "-2.1 m", "-1.5 m"});
  // the base's bottom edge: its middle (0, −0.5), moved 0.05 inside
  CHECK(list.lines()[0] == "text Label#0 (0,-0.45) \"-2.1 m\"");
}

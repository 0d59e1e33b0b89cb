// The separating-axis overlay: the notes' reference edge, incident vertex and separation, and every
// other candidate axis labeled with its own separation (recorded as a draw list).
#include "sim/describe/separating_axes.h"

#include <doctest/doctest.h>

#include <algorithm>

#include "render/draw/draw_list.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"

using render::draw::DrawList;

namespace {

// a unit box 0.1 m above a static 2 × 1 base
const sim::scene::SceneDef kPair = sim::yaml::loadSceneText(R"(
bodies:
  - {name: base, shape: {box: [2, 1]}, static: true}
  - {name: box, shape: {box: [1, 1]}, position: [0, 1.1]}
)",
                                                            "inline.yaml");

std::vector<std::string> texts(const DrawList& list) {
  std::vector<std::string> out;
  for (const auto& c : list.calls())
    if (c.kind == DrawList::Kind::Label) out.push_back(c.text);
  return out;
}

}  // namespace

TEST_CASE("an edge's separation is the least distance of the other polygon's vertices past it") {
  const sim::world::World w = sim::scene::buildWorld(kPair);
  // the base's edges from (−1, −0.5) counter-clockwise: bottom, right, top, left
  CHECK(sim::describe::edgeSeparation(w.bodies[0], 0, w.bodies[1]) == doctest::Approx(-2.1));
  CHECK(sim::describe::edgeSeparation(w.bodies[0], 1, w.bodies[1]) == doctest::Approx(-1.5));
  CHECK(sim::describe::edgeSeparation(w.bodies[0], 2, w.bodies[1]) == doctest::Approx(0.1));
  CHECK(sim::describe::edgeSeparation(w.bodies[1], 0, w.bodies[0]) == doctest::Approx(0.1));
}

TEST_CASE("the reference edge, the incident vertex and the separation; every other axis on request") {
  const sim::world::World w = sim::scene::buildWorld(kPair);
  DrawList list;
  render::draw::PhysicsDraw physics(list);
  sim::describe::describeSeparatingAxes(w, 1.0, 0.05, physics);
  const std::vector<std::string> lines = list.lines();
  REQUIRE(lines.size() == 3);
  // the base's top face is the reference edge, the box's lower-left corner the incident vertex
  CHECK(lines[0] == "segment ReferenceEdge#0 (1,0.5) (-1,0.5)");
  CHECK(lines[1] == "point IncidentVertex#1 (-0.5,0.6)");
  // its separation, a label on the point 0.05 inside the base below the edge's middle (the frame's
  // label placer may move it off another)
  CHECK(lines[2] == "label Label#0 (0,0.45) beyond (0,0) \"separation 0.100 m\"");

  // every axis: the 7 other edges of both polygons, each labeled inside its own polygon
  DrawList every;
  render::draw::PhysicsDraw everyPhysics(every);
  sim::describe::describeSeparatingAxes(w, 1.0, 0.05, everyPhysics, true);
  std::vector<std::string> candidates = texts(every);
  REQUIRE(candidates.size() == 8);
  candidates.erase(candidates.begin());
  CHECK(candidates == std::vector<std::string>{"−2.10 m", "−1.50 m", "−1.50 m", "0.100 m", "−1.50 m", "−2.10 m", "−1.50 m"});
  // the base's bottom edge: its middle (0, −0.5), moved 0.05 inside
  CHECK(every.lines()[3] == "label Label#0 (0,-0.45) beyond (0,0) \"−2.10 m\"");
  // pairs farther apart than the gap asked for are not drawn
  DrawList far;
  render::draw::PhysicsDraw farPhysics(far);
  sim::describe::describeSeparatingAxes(w, 0.05, 0.05, farPhysics);
  CHECK(far.empty());
}

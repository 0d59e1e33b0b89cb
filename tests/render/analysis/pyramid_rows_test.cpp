#include "render/analysis/pyramid_rows.h"

#include <doctest/doctest.h>

#include "sim/yaml/scene_yaml.h"

namespace {

using sim::core::Vec2;

// Box2D's testbed pyramid (1 m boxes 1.125 m apart, each row 0.25 m above the one below), base
// `base`, on a ground box; the spacings are binary fractions, so positions compare exactly
std::string droppedPyramid(int base, double nudge = 0.0) {
  std::string yaml = "bodies:\n  - {name: ground, shape: {box: [80, 1]}, static: true, position: [0, -0.5]}\n";
  for (int row = 0; row < base; ++row)
    for (int k = 0; k < base - row; ++k) {
      const double x = -7.0 + 0.5625 * row + 1.125 * k + (row == 1 && k == 1 ? nudge : 0.0);
      const double y = 0.75 + 1.25 * row;
      yaml += "  - {name: p" + std::to_string(row) + "_" + std::to_string(k) + ", shape: {box: [1, 1]}, position: [" +
              std::to_string(x) + ", " + std::to_string(y) + "]}\n";
    }
  return yaml;
}

std::vector<sim::scene::BodyDef> bodiesOf(const std::string& yaml) {
  return sim::yaml::readModel(sim::yaml::sceneSourceText(yaml, "inline.yaml")).bodies;
}

}  // namespace

TEST_CASE("a listed pyramid is read as its bottom row, spacing and row shift, and rebuilt exactly at its own base") {
  const auto bodies = bodiesOf(droppedPyramid(4));
  const render::analysis::PyramidReading reading = render::analysis::readPyramid(bodies);
  REQUIRE(reading.rows);
  const render::analysis::PyramidRows& rows = *reading.rows;
  CHECK(rows.base == 4);
  CHECK(rows.origin == Vec2(-7.0, 0.75));
  CHECK(rows.along == Vec2(1.125, 0.0));
  CHECK(rows.up == Vec2(0.5625, 1.25));
  const auto same = render::analysis::pyramidOfBase(bodies, rows, 4);
  REQUIRE(same.size() == bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) CHECK(same[i].position == bodies[i].position);
}

TEST_CASE("a pyramid grown to another base keeps its bottom row's centre, its spacing and its shift") {
  const auto bodies = bodiesOf(droppedPyramid(4));
  const auto rows = *render::analysis::readPyramid(bodies).rows;
  const auto grown = render::analysis::pyramidOfBase(bodies, rows, 7);
  // the ground, then 7 + 6 + ... + 1 boxes
  REQUIRE(grown.size() == 1 + 28);
  CHECK(grown[0].isStatic);
  // the listed bottom row spans -7 .. -3.625 (centre -5.3125); the base-7 row is centred there too
  CHECK(grown[1].position == Vec2(-5.3125 - 3.0 * 1.125, 0.75));
  CHECK(grown[7].position == Vec2(-5.3125 + 3.0 * 1.125, 0.75));
  CHECK(grown[1].name == "b1_1");
  // the top box: six rows up, straight above the bottom row's centre
  CHECK(grown.back().name == "b7_1");
  CHECK(grown.back().position == Vec2(-5.3125, 0.75 + 6 * 1.25));
  for (std::size_t i = 1; i < grown.size(); ++i) CHECK_FALSE(grown[i].isStatic);
  // shrunk to a single box: above the centre, on the bottom row
  const auto one = render::analysis::pyramidOfBase(bodies, rows, 1);
  REQUIRE(one.size() == 2);
  CHECK(one[1].position == Vec2(-5.3125, 0.75));
}

TEST_CASE("bodies that are not a pyramid are refused, naming the box out of place") {
  const render::analysis::PyramidReading moved = render::analysis::readPyramid(bodiesOf(droppedPyramid(4, 0.01)));
  CHECK_FALSE(moved.rows);
  CHECK(moved.problem.find("'p1_1'") != std::string::npos);
  CHECK(moved.problem.find("row 2, place 2") != std::string::npos);

  // a bottom row of 4 and 5 boxes in all
  std::string partial = droppedPyramid(4);
  partial = partial.substr(0, partial.find("  - {name: p1_1"));
  const render::analysis::PyramidReading counted = render::analysis::readPyramid(bodiesOf(partial));
  CHECK_FALSE(counted.rows);
  CHECK(counted.problem.find("pyramid of 10 boxes; the scene has 5") != std::string::npos);

  // every box must be a copy of the first: the grown pyramid is made of copies of it
  std::string heavy = droppedPyramid(4);
  heavy.replace(heavy.find("position: [-6.4375"), 0, "mass: 5, ");
  const render::analysis::PyramidReading unlike = render::analysis::readPyramid(bodiesOf(heavy));
  CHECK_FALSE(unlike.rows);
  CHECK(unlike.problem.find("'p1_0' differs from the first box") != std::string::npos);

  const render::analysis::PyramidReading row = render::analysis::readPyramid(
      bodiesOf("bodies:\n  - {name: a, shape: {box: [1, 1]}}\n  - {name: b, shape: {box: [1, 1]}, position: [2, 0]}\n"
               "  - {name: c, shape: {box: [1, 1]}, position: [4, 0]}\n"));
  CHECK_FALSE(row.rows);
  CHECK(row.problem.find("a second row must follow") != std::string::npos);
}

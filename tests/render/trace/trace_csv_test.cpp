// The trace CSV read back against a scene: columns in any order, rows interpolated linearly to any
// time (before or after an event at one time), and every fault at its FILE:LINE:COL.
#include <doctest/doctest.h>

#include <sstream>

#include "render/trace/trace_csv.h"
#include "render/trace/trace_writer.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"
#include "support/scene_error_check.h"

using namespace render::trace;

namespace {

const sim::scene::SceneDef kScene = sim::yaml::loadSceneText(R"(
bodies:
  - {name: a, shape: {circle: 0.5}, velocity: [1, 0]}
  - {name: b, shape: {circle: 0.5}, position: [3, 0]}
)",
                                                             "two.yaml");

Trace read(const std::string& text) { return traceText(text, "theirs.csv", kScene); }

}  // namespace

TEST_CASE("what simulate --trace writes reads back, row for row") {
  sim::world::World world = sim::scene::buildWorld(kScene);
  std::ostringstream out;
  render::trace::TraceWriter writer(out, kScene);
  writer.rows(world);
  world.advanceTo(0.1, &writer);
  const Trace t = read(out.str());
  REQUIRE(t.bodies.size() == 2);
  CHECK(t.rows == 2 * t.bodies[0].size());
  CHECK(t.bodies[0].back().t == world.time);
  CHECK(t.bodies[0].back().x == world.bodies[0].x.x());
  CHECK(t.bodies[0].back().kineticEnergy == doctest::Approx(0.5 * world.bodies[0].mass));
}

TEST_CASE("columns in any order, kinetic_energy optional; values linear between rows") {
  const Trace t = read("body,t,y,x,angle,omega,vx,vy\na,0,0,0,0,1,1,0\na,0.5,1,2,0.5,1,1,0\n");
  TraceSample s;
  REQUIRE(sampleAt(t.bodies[0], 0.125, s));
  CHECK(s.x == doctest::Approx(0.5));
  CHECK(s.y == doctest::Approx(0.25));
  CHECK(s.angle == doctest::Approx(0.125));
  CHECK_FALSE(sampleAt(t.bodies[0], 0.6, s));
  CHECK(t.bodies[1].empty());
}

TEST_CASE("two rows at one time: the later after an event, the earlier before it") {
  const Trace t = read("t,body,x,y,angle,vx,vy,omega\n0,a,0,0,0,1,0,0\n1,a,1,0,0,1,0,0\n1,a,1,0,0,-1,0,0\n2,a,0,0,0,-1,0,0\n");
  TraceSample s;
  REQUIRE(sampleAt(t.bodies[0], 1.0, s));
  CHECK(s.vx == -1.0);
  REQUIRE(sampleAt(t.bodies[0], 1.0, s, true));
  CHECK(s.vx == 1.0);
  REQUIRE(sampleAt(t.bodies[0], 1.5, s));
  CHECK(s.x == doctest::Approx(0.5));
  CHECK(s.vx == -1.0);
}

TEST_CASE("a malformed trace is refused at its line and column") {
  const auto load = [](const std::string& text, const std::string& file, const std::string&) {
    return traceText(text, file, kScene);
  };
  const std::string header = "t,body,x,y,angle,vx,vy,omega\n";
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,a,0,0,0,1,0,0\n0.1,a,0.1,nan,0,1,0,0\n", 3, 11,
                                 {"finite number", "'y'"});
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,c,0,0,0,1,0,0\n", 2, 3, {"no body named 'c'", "a, b"});
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,a,0,0,0,1,0\n", 2, 1, {"expected 8 comma-separated values"});
  scene_errors::expectSceneError(load, "theirs.csv", header + "1,a,0,0,0,1,0,0\n0.5,a,0,0,0,1,0,0\n", 3, 1,
                                 {"time goes back for 'a'", "line 2"});
  scene_errors::expectSceneError(load, "theirs.csv", "t,body,x,y,angle,vx,vy\n0,a,0,0,0,1,0\n", 1, 1, {"no column 'omega'"});
  scene_errors::expectSceneError(load, "theirs.csv", header, 1, 1, {"no rows"});
}

TEST_CASE("what the trace writer writes of names with commas, quotes and line breaks reads back") {
  const sim::scene::SceneDef scene = sim::yaml::loadSceneText(R"(
bodies:
  - {name: "a,b", shape: {circle: 0.5}, velocity: [1, 0]}
  - {name: "say \"hi\"\nnow", shape: {circle: 0.5}, position: [3, 0]}
  - {name: "Stoß", shape: {circle: 0.5}, position: [1.0e-310, 6]}
)",
                                                              "names.yaml");
  sim::world::World world = sim::scene::buildWorld(scene);
  std::ostringstream out;
  render::trace::TraceWriter writer(out, scene);
  writer.rows(world);
  world.advanceTo(0.01, &writer);
  const Trace t = traceText(out.str(), "names.csv", scene);
  REQUIRE(t.bodies.size() == 3);
  CHECK(t.bodies[0].size() == t.bodies[1].size());
  CHECK(t.bodies[1].size() == t.bodies[2].size());
  CHECK(t.bodies[0].back().x == world.bodies[0].x.x());
  // a subnormal reads back as itself
  CHECK(t.bodies[2].front().x == 1.0e-310);
}

TEST_CASE("a byte order mark before the header is ignored; a quote left open is refused where it opens") {
  const Trace t = read("\xEF\xBB\xBFt,body,x,y,angle,vx,vy,omega\n0,\"a\",0,0,0,1,0,0\n");
  CHECK(t.bodies[0].size() == 1);
  const auto load = [](const std::string& text, const std::string& file, const std::string&) {
    return traceText(text, file, kScene);
  };
  const std::string header = "t,body,x,y,angle,vx,vy,omega\n";
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,\"a,0,0,0,1,0,0\n", 2, 3, {"no closing quote"});
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,\"a\"x,0,0,0,1,0,0\n", 2, 6,
                                 {"expected a comma after the closing quote"});
  // a control character of a name not in the scene is shown escaped, never sent to the terminal
  scene_errors::expectSceneError(load, "theirs.csv", header + "0,\x1b[31m,0,0,0,1,0,0\n", 2, 3, {"no body named '\\x1b[31m'"});
}

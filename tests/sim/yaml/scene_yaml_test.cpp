// The YAML scene loader: every bad input is a SceneError at the right FILE:LINE:COL with a message
// that names the fault (and, for misspelled keys, the nearest valid key); good input gives the
// values and defaults the format documents; variants deep-merge over the scene.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <unistd.h>

#include "sim/yaml/scene_yaml.h"
#include "support/scene_error_check.h"

namespace {

const scene_errors::InlineSceneErrors expectSceneError{sim::yaml::loadSceneText};

// one body `a` (a unit circle) on lines 1-3; tests append lines 4, 5, ...
const std::string kOneBody =
    "bodies:\n"
    "  - name: a\n"
    "    shape: {circle: 1}\n";

// the model of a scene whose bodies may have the renderer's keys too, as the command line reads it
sim::scene::SceneDef load(const std::string& text, const std::string& variant = "") {
  return sim::yaml::readModel(sim::yaml::sceneSourceText(text, scene_errors::kInlineFile, variant), {{}, {"color", "label"}});
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// not a scene at all

TEST_CASE("invalid YAML is reported at the parser's position") {
  // an unclosed bracket: the parser finds out at the end of the input (line 4, after the last newline)
  EXPECT_SCENE_ERROR(
      "name: x\n"
      "bodies: [\n"
      "  {name: a, shape: {circle: 1}}\n",
      4, 1, {"invalid YAML", "sequence"});
  // an unclosed brace inside a block list
  EXPECT_SCENE_ERROR(
      "name: x\n"
      "bodies:\n"
      "  - name: a\n"
      "    shape: {circle: 1\n",
      5, 1, {"invalid YAML", "map"});
  // a second ':' on one line: at the second colon
  EXPECT_SCENE_ERROR("name: x: y\n" + kOneBody, 1, 8, {"invalid YAML", "illegal map value"});
  // a key indented under a scalar
  EXPECT_SCENE_ERROR(
      "name: x\n"
      "  bad: 1\n" +
          kOneBody,
      2, 6, {"invalid YAML"});
}

TEST_CASE("an empty document is an error at 1:1") {
  EXPECT_SCENE_ERROR("", 1, 1, {"empty", "bodies"});
  EXPECT_SCENE_ERROR("# only a comment\n", 1, 1, {"empty", "bodies"});
  EXPECT_SCENE_ERROR("---\n", 1, 1, {"empty"});
}

TEST_CASE("the top level must be a map") {
  EXPECT_SCENE_ERROR("- a\n- b\n", 1, 1, {"a scene is a map", "bodies", "got a list"});
  EXPECT_SCENE_ERROR("hello\n", 1, 1, {"a scene is a map", "'hello'"});
}

TEST_CASE("bodies: is required and must be a non-empty list") {
  EXPECT_SCENE_ERROR("name: x\n", 1, 1, {"needs 'bodies'"});
  EXPECT_SCENE_ERROR("name: x\nbodies: []\n", 2, 9, {"'bodies' must be a list of at least one body"});
  EXPECT_SCENE_ERROR("name: x\nbodies: 5\n", 2, 9, {"'bodies' must be a list"});
}

// ---------------------------------------------------------------------------------------------
// unknown keys: the message names the key, where it is, and the nearest valid key

TEST_CASE("unknown keys name the nearest valid key") {
  SUBCASE("top level") {
    EXPECT_SCENE_ERROR("durtion: 1\n" + kOneBody, 1, 1, {"unknown key 'durtion'", "the scene", "did you mean 'duration'"});
    EXPECT_SCENE_ERROR(kOneBody + "varaints: {}\n", 4, 1, {"unknown key 'varaints'", "did you mean 'variants'"});
  }
  SUBCASE("in a body") {
    EXPECT_SCENE_ERROR(kOneBody + "    desity: 2\n", 4, 5, {"unknown key 'desity'", "a body", "did you mean 'density'"});
    EXPECT_SCENE_ERROR(kOneBody + "    angular_velocty: 2\n", 4, 5,
                       {"unknown key 'angular_velocty'", "did you mean 'angular_velocity'"});
  }
  SUBCASE("in a shape") {
    EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {cirle: 1}\n", 3, 13, {"unknown key 'cirle'", "did you mean 'circle'"});
    // two swapped letters are one edit
    EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {bxo: [1, 1]}\n", 3, 13, {"unknown key 'bxo'", "did you mean 'box'"});
  }
  // a key far from every valid one gets the list, not a guess: 'rectangle' is no 'circle'
  SUBCASE("far from every key: the valid keys listed") {
    for (const std::string shape : {"rectangle", "capsule"}) {
      EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {" + shape + ": 1}\n", 3, 13,
                         {"unknown key '" + shape + "' in shape", "choose one of: box, polygon, circle, plane"});
      std::string message;
      try {
        sim::yaml::loadSceneText("bodies:\n  - name: a\n    shape: {" + shape + ": 1}\n", scene_errors::kInlineFile, "");
      } catch (const sim::yaml::SceneError& e) {
        message = e.what();
      }
      CHECK(message.find("did you mean") == std::string::npos);
    }
    // a two-letter key one swap away is still two letters in three: the list, which has 'dt'
    EXPECT_SCENE_ERROR("sim:\n  integrator: rk4\n  td: 0.1\n" + kOneBody, 3, 3,
                       {"unknown key 'td'", "choose one of: integrator, dt,"});
  }
  SUBCASE("in sim:") {
    EXPECT_SCENE_ERROR("sim: {intgrator: rk4}\n" + kOneBody, 1, 7,
                       {"unknown key 'intgrator'", "sim", "did you mean 'integrator'"});
  }
  SUBCASE("in world:") {
    EXPECT_SCENE_ERROR("world:\n  gravty: [0, 1]\n" + kOneBody, 2, 3,
                       {"unknown key 'gravty'", "world", "did you mean 'gravity'"});
  }
  SUBCASE("in a force") {
    EXPECT_SCENE_ERROR(kOneBody +
                           "forces:\n"
                           "  - type: spring\n"
                           "    body: a\n"
                           "    anchor: [0, 0]\n"
                           "    stifness: 1\n",
                       8, 5, {"unknown key 'stifness'", "a spring", "did you mean 'stiffness'"});
    EXPECT_SCENE_ERROR(kOneBody + "forces:\n  - {type: force, body: a, forse: [1, 0]}\n", 5, 28,
                       {"unknown key 'forse'", "a force", "did you mean 'force'"});
    EXPECT_SCENE_ERROR(kOneBody + "forces:\n  - {type: drag, body: a, lineer: 1}\n", 5, 27,
                       {"unknown key 'lineer'", "a drag", "did you mean 'linear'"});
  }
  SUBCASE("in an event") {
    EXPECT_SCENE_ERROR(kOneBody +
                           "events:\n"
                           "  - time: 0.5\n"
                           "    body: a\n"
                           "    impluse: [1, 0]\n",
                       7, 5, {"unknown key 'impluse'", "an event", "did you mean 'impulse'"});
  }
  SUBCASE("in an expect entry") {
    EXPECT_SCENE_ERROR(kOneBody +
                           "expect:\n"
                           "  - time: 0.5\n"
                           "    body: a\n"
                           "    velocty: [1, 0]\n",
                       7, 5, {"unknown key 'velocty'", "an expect entry", "did you mean 'velocity'"});
  }
}

// ---------------------------------------------------------------------------------------------
// wrong types

TEST_CASE("a value of the wrong type is reported at the value") {
  SUBCASE("a string where a number belongs") {
    EXPECT_SCENE_ERROR(kOneBody + "    mass: heavy\n", 4, 11, {"expected a number for 'mass'", "'heavy'"});
    EXPECT_SCENE_ERROR("duration: long\n" + kOneBody, 1, 11, {"expected a number for 'duration'", "'long'"});
    EXPECT_SCENE_ERROR("sim: {dt: small}\n" + kOneBody, 1, 11, {"expected a number for 'dt'", "'small'"});
  }
  SUBCASE("a map where [x, y] belongs") {
    EXPECT_SCENE_ERROR(kOneBody + "    position: {x: 1, y: 2}\n", 4, 15, {"expected [x, y] for 'position'", "a map"});
    EXPECT_SCENE_ERROR("world: {gravity: {y: -9.81}}\n" + kOneBody, 1, 18, {"expected [x, y] for 'gravity'", "a map"});
  }
  SUBCASE("a vector of 3 numbers") {
    EXPECT_SCENE_ERROR(kOneBody + "    position: [1, 2, 3]\n", 4, 15, {"expected [x, y] for 'position'"});
    EXPECT_SCENE_ERROR(kOneBody + "    velocity: [1, 2, 3]\n", 4, 15, {"expected [x, y] for 'velocity'"});
    EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [1, 2, 3]}\n", 3, 18, {"expected [x, y] for 'box'"});
  }
  SUBCASE("a list where a number belongs") {
    EXPECT_SCENE_ERROR(kOneBody + "    angle: [1]\n", 4, 12, {"expected a number for 'angle'", "a list"});
  }
  SUBCASE("a number where a map belongs") {
    EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: 3\n", 3, 12, {"expected a map for shape", "'3'"});
    EXPECT_SCENE_ERROR("bodies:\n  - 7\n", 2, 5, {"expected a map for a body", "'7'"});
  }
  SUBCASE("something other than true/false for static") {
    EXPECT_SCENE_ERROR(kOneBody + "    static: maybe\n", 4, 13, {"expected true or false for 'static'"});
  }
}

// ---------------------------------------------------------------------------------------------
// bodies and references to them

TEST_CASE("every body needs a unique name") {
  // at the body's map: its first key
  EXPECT_SCENE_ERROR("bodies:\n  - shape: {circle: 1}\n", 2, 5, {"every body needs 'name'"});
  EXPECT_SCENE_ERROR("bodies:\n  - {shape: {circle: 1}}\n", 2, 5, {"every body needs 'name'"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: \"\"\n    shape: {circle: 1}\n", 2, 5, {"name cannot be empty"});
  // at the second body's name
  EXPECT_SCENE_ERROR(kOneBody +
                         "  - name: b\n"
                         "    shape: {circle: 1}\n"
                         "  - name: a\n"
                         "    shape: {circle: 2}\n",
                     6, 11, {"duplicate body name 'a'"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n", 2, 5, {"body 'a' needs 'shape'"});
}

TEST_CASE("a reference to a body that does not exist lists the bodies") {
  const std::string two = kOneBody + "  - name: c\n    shape: {circle: 1}\n";  // bodies a, c; 5 lines
  SUBCASE("force") {
    EXPECT_SCENE_ERROR(two + "forces:\n  - {type: force, body: nope, force: [1, 0]}\n", 7, 25,
                       {"no body named 'nope'", "the bodies are: a, c"});
  }
  SUBCASE("drag") {
    EXPECT_SCENE_ERROR(two + "forces:\n  - {type: drag, body: nope, linear: 1}\n", 7, 24,
                       {"no body named 'nope'", "the bodies are: a, c"});
  }
  SUBCASE("spring body") {
    EXPECT_SCENE_ERROR(two + "forces:\n  - {type: spring, body: nope, anchor: [0, 0], stiffness: 1}\n", 7, 26,
                       {"no body named 'nope'", "the bodies are: a, c"});
  }
  SUBCASE("spring body2") {
    EXPECT_SCENE_ERROR(two +
                           "forces:\n"
                           "  - type: spring\n"
                           "    body: a\n"
                           "    body2: b\n"
                           "    stiffness: 1\n",
                       9, 12, {"no body named 'b'", "the bodies are: a, c"});
  }
  SUBCASE("event") {
    EXPECT_SCENE_ERROR(two + "events:\n  - {time: 0.5, body: nope, impulse: [1, 0]}\n", 7, 23,
                       {"no body named 'nope'", "the bodies are: a, c"});
  }
  SUBCASE("expect") {
    EXPECT_SCENE_ERROR(two + "expect:\n  - {time: 0.5, body: nope, angle: 0}\n", 7, 23,
                       {"no body named 'nope'", "the bodies are: a, c"});
  }
}

// ---------------------------------------------------------------------------------------------
// polygons: reported at the shape

namespace {
std::string polygonScene(const std::string& vertices) { return "bodies:\n  - name: a\n    shape: {polygon: " + vertices + "}\n"; }
}  // namespace

TEST_CASE("a non-convex polygon is rejected") {
  EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [2, 0], [1, 0.2], [1, 2]]"), 3, 12, {"non-convex polygon"});
  // an L shape
  EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]"), 3, 12, {"non-convex polygon"});
}

TEST_CASE("a degenerate polygon is rejected") {
  SUBCASE("collinear vertices") {
    EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [1, 0], [2, 0]]"), 3, 12, {"degenerate polygon"});
    EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [1, 0], [2, 0], [1, 1]]"), 3, 12, {"degenerate polygon", "line"});
  }
  SUBCASE("repeated vertices") {
    EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [1, 0], [1, 0], [1, 1]]"), 3, 12, {"degenerate polygon"});
    EXPECT_SCENE_ERROR(polygonScene("[[1, 1], [1, 1], [1, 1]]"), 3, 12, {"degenerate polygon", "coincide"});
  }
  SUBCASE("fewer than 3 vertices") {
    EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [1, 0]]"), 3, 12, {"at least 3 vertices", "got 2"});
    EXPECT_SCENE_ERROR(polygonScene("[]"), 3, 12, {"at least 3 vertices", "got 0"});
  }
  SUBCASE("a vertex that is not [x, y]") {
    EXPECT_SCENE_ERROR(polygonScene("[[0, 0], [1, 0, 5], [1, 1]]"), 3, 31, {"expected [x, y]", "polygon vertex"});
  }
}

TEST_CASE("a self-intersecting polygon (a pentagram) is rejected") {
  // a regular pentagon's vertices at 90° + 72° k, taken every second one: k = 0, 2, 4, 1, 3;
  // every turn is a left turn, but the boundary winds twice
  const std::string star =
      "[[0, 1], [-0.5877852522924731, -0.8090169943749475], [0.9510565162951535, 0.30901699437494745], "
      "[-0.9510565162951535, 0.30901699437494745], [0.5877852522924731, -0.8090169943749475]]";
  EXPECT_SCENE_ERROR(polygonScene(star), 3, 12, {"self-intersecting polygon"});
  // the same star walked the other way
  const std::string reversed =
      "[[0, 1], [0.5877852522924731, -0.8090169943749475], [-0.9510565162951535, 0.30901699437494745], "
      "[0.9510565162951535, 0.30901699437494745], [-0.5877852522924731, -0.8090169943749475]]";
  EXPECT_SCENE_ERROR(polygonScene(reversed), 3, 12, {"self-intersecting polygon"});
  // the pentagon itself, in order, is fine
  const sim::scene::SceneDef ok =
      load(polygonScene("[[0, 1], [-0.9510565162951535, 0.30901699437494745], [-0.5877852522924731, -0.8090169943749475], "
                        "[0.5877852522924731, -0.8090169943749475], [0.9510565162951535, 0.30901699437494745]]"));
  CHECK(ok.bodies.at(0).shape.vertices.size() == 5);
}

TEST_CASE("a polygon given clockwise is accepted and stored counter-clockwise") {
  const sim::scene::SceneDef s = load(polygonScene("[[0, 0], [0, 1], [2, 1], [2, 0]]"));
  const sim::core::Shape& shape = s.bodies.at(0).shape;
  REQUIRE(shape.kind == sim::core::ShapeKind::Polygon);
  REQUIRE(shape.vertices.size() == 4);
  double twiceArea = 0.0;
  for (size_t i = 0; i < 4; ++i) twiceArea += sim::core::cross(shape.vertices[i], shape.vertices[(i + 1) % 4]);
  CHECK(twiceArea == doctest::Approx(4.0));
  CHECK(sim::core::areaProperties(shape).area == doctest::Approx(2.0));
}

// ---------------------------------------------------------------------------------------------
// numbers that must be positive and finite

namespace {
const std::vector<std::string> kNotPositive = {"0", "-1", "-0.5", ".nan", ".NaN", ".inf", "-.inf"};
}

TEST_CASE("mass, inertia and density must be positive finite numbers") {
  for (const std::string key : {"mass", "inertia", "density"})
    for (const std::string& value : kNotPositive) {
      CAPTURE(key);
      CAPTURE(value);
      // "    key: value" on line 4
      EXPECT_SCENE_ERROR(kOneBody + "    " + key + ": " + value + "\n", 4, static_cast<int>(4 + key.size() + 2 + 1),
                         {"'" + key + "' must be a positive finite number", "got " + value});
    }
}

TEST_CASE("a circle radius must be a positive finite number") {
  for (const std::string& value : kNotPositive) {
    CAPTURE(value);
    EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {circle: " + value + "}\n", 3, 21,
                       {"'circle' must be a positive finite number", "got " + value});
  }
}

TEST_CASE("a box size must be positive and finite") {
  // zero or negative: at the [w, h]
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [0, 1]}\n", 3, 18, {"box width and height must be positive"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [1, 0]}\n", 3, 18, {"box width and height must be positive"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [-1, 1]}\n", 3, 18, {"box width and height must be positive"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [1, -2]}\n", 3, 18, {"box width and height must be positive"});
  // not finite: at the number itself
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [.nan, 1]}\n", 3, 19, {"'box' must be a finite number", ".nan"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [1, .inf]}\n", 3, 22, {"'box' must be a finite number", ".inf"});
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {box: [-.inf, 1]}\n", 3, 19, {"'box' must be a finite number"});
}

TEST_CASE("dt and duration must be positive finite numbers") {
  for (const std::string& value : kNotPositive) {
    CAPTURE(value);
    EXPECT_SCENE_ERROR("sim: {dt: " + value + "}\n" + kOneBody, 1, 11, {"'dt' must be a positive finite number", "got " + value});
    EXPECT_SCENE_ERROR("sim:\n  integrator: rk4\n  dt: " + value + "\n" + kOneBody, 3, 7,
                       {"'dt' must be a positive finite number"});
    EXPECT_SCENE_ERROR("duration: " + value + "\n" + kOneBody, 1, 11,
                       {"'duration' must be a positive finite number", "got " + value});
  }
}

TEST_CASE("other numbers must be finite") {
  EXPECT_SCENE_ERROR(kOneBody + "    angle: .nan\n", 4, 12, {"'angle' must be a finite number"});
  EXPECT_SCENE_ERROR(kOneBody + "    position: [0, .inf]\n", 4, 19, {"'position' must be a finite number"});
  EXPECT_SCENE_ERROR("world: {gravity: [0, -.inf]}\n" + kOneBody, 1, 22, {"'gravity' must be a finite number"});
}

// ---------------------------------------------------------------------------------------------
// times

TEST_CASE("an event time must lie in [0, duration]") {
  const std::string scene = "duration: 2\n" + kOneBody + "events:\n";  // the event is on line 6
  EXPECT_SCENE_ERROR(scene + "  - {time: 2.5, body: a, impulse: [1, 0]}\n", 6, 12,
                     {"event time 2.5 is outside the scene's duration [0, 2]", "duration"});
  EXPECT_SCENE_ERROR(scene + "  - {time: -0.1, body: a, impulse: [1, 0]}\n", 6, 12,
                     {"event time -0.1 is outside the scene's duration [0, 2]"});
  EXPECT_SCENE_ERROR(scene + "  - {time: .nan, body: a, impulse: [1, 0]}\n", 6, 12, {"'time' must be a finite number"});
  // the default duration is 1 s
  EXPECT_SCENE_ERROR(kOneBody + "events:\n  - {time: 1.5, body: a, impulse: [1, 0]}\n", 5, 12, {"[0, 1]"});
  // both ends are inside
  const sim::scene::SceneDef s =
      load(scene + "  - {time: 0, body: a, impulse: [1, 0]}\n  - {time: 2, body: a, impulse: [0, 1]}\n");
  REQUIRE(s.events.size() == 2);
  CHECK(s.events[0].time == 0.0);
  CHECK(s.events[1].time == 2.0);
}

TEST_CASE("an expect time must lie in [0, duration]") {
  const std::string scene = "duration: 2\n" + kOneBody + "expect:\n";
  EXPECT_SCENE_ERROR(scene + "  - {time: 3, body: a, angle: 0}\n", 6, 12,
                     {"expect time 3 is outside the scene's duration [0, 2]"});
  EXPECT_SCENE_ERROR(scene + "  - {time: -1, angular_momentum: 0}\n", 6, 12, {"expect time -1 is outside"});
  const sim::scene::SceneDef s = load(scene + "  - {time: 2, body: a, angle: 0}\n");
  REQUIRE(s.expects.size() == 1);
  CHECK(s.expects[0].time == 2.0);
  CHECK(s.expects[0].loc.line == 6);
}

TEST_CASE("energy_never_rises: over the whole run unless a time is given, on its own, and only true") {
  const std::string scene = "duration: 2\n" + kOneBody + "expect:\n";
  const sim::scene::SceneDef s =
      load(scene + "  - {energy_never_rises: true, tolerance: 1e-6}\n  - {energy_never_rises: yes, time: 1}\n");
  REQUIRE(s.expects.size() == 2);
  CHECK(s.expects[0].energyNeverRises);
  CHECK(s.expects[0].time == 2.0);
  CHECK(s.expects[0].tolerance == 1e-6);
  CHECK(s.expects[1].time == 1.0);
  EXPECT_SCENE_ERROR(scene + "  - {energy_never_rises: false}\n", 6, 26, {"checks nothing", "remove the entry"});
  EXPECT_SCENE_ERROR(scene + "  - {energy_never_rises: true, body: a, angle: 0}\n", 6, 38,
                     {"'body' is checked at one time", "an entry of its own"});
  EXPECT_SCENE_ERROR(scene + "  - {energy_never_rises: true, time: 3}\n", 6, 38, {"outside the scene's duration"});
  // any other entry still needs its time
  EXPECT_SCENE_ERROR(scene + "  - {total_energy: 1}\n", 6, 5, {"time"});
}

// ---------------------------------------------------------------------------------------------
// integrators and variants by name

TEST_CASE("an unknown integrator lists the integrators") {
  EXPECT_SCENE_ERROR("sim: {integrator: rk5}\n" + kOneBody, 1, 19,
                     {"unknown integrator 'rk5'", "choose one of: ", "explicit_euler", "symplectic_euler", "midpoint", "rk4"});
}

namespace {
// variants "zeta", "alpha", "empty", in that (non-alphabetical) order; see the line numbers on the right
const std::string kVariantScene =
    "name: merged\n"                                             // 1
    "duration: 2\n"                                              // 2
    "sim: {integrator: rk4, dt: 0.01}\n"                         // 3
    "world: {gravity: [0, -9.81]}\n"                             // 4
    "bodies:\n"                                                  // 5
    "  - name: a\n"                                              // 6
    "    shape: {box: [1, 2]}\n"                                 // 7
    "    mass: 3\n"                                              // 8
    "    position: [1, 2]\n"                                     // 9
    "    friction: 0.25\n"                                       // 10
    "  - name: b\n"                                              // 11
    "    shape: {circle: 0.5}\n"                                 // 12
    "events:\n"                                                  // 13
    "  - {time: 0.5, body: a, impulse: [1, 0]}\n"                // 14
    "  - {time: 1.0, body: b, impulse: [0, 1]}\n"                // 15
    "variants:\n"                                                // 16
    "  zeta:\n"                                                  // 17
    "    sim: {dt: 0.001}\n"                                     // 18
    "    bodies:\n"                                              // 19
    "      - {name: a, velocity: [4, 5], mass: 6}\n"             // 20
    "      - {name: c, shape: {circle: 1}, position: [7, 8]}\n"  // 21
    "    events:\n"                                              // 22
    "      - {time: 1.5, body: c, impulse: [2, 0]}\n"            // 23
    "  alpha:\n"                                                 // 24
    "    world: {gravity: [0, 0]}\n"                             // 25
    "    duration: 3\n"                                          // 26
    "  empty:\n";                                                // 27
}  // namespace

TEST_CASE("an unknown variant lists the known variants") {
  EXPECT_SCENE_ERROR(kVariantScene, 17, 0, {"unknown variant 'nope'", "zeta, alpha, empty"}, "nope");
  EXPECT_SCENE_ERROR(kOneBody, 1, 1, {"unknown variant 'nope'", "no variants"}, "nope");
}

TEST_CASE("variants must be a map of maps") {
  EXPECT_SCENE_ERROR(kOneBody + "variants: [a, b]\n", 4, 11, {"'variants' must be a map"});
  EXPECT_SCENE_ERROR(kOneBody + "variants:\n  v: 3\n", 5, 6, {"variant 'v' must be a map of changes"});
  EXPECT_SCENE_ERROR(kOneBody + "variants:\n  v:\n    variants: {w: {}}\n", 6, 15, {"a variant cannot define variants"}, "v");
}

// ---------------------------------------------------------------------------------------------
// good scenes

TEST_CASE("a valid scene loads with its values") {
  const std::string text =
      "name: full\n"
      "description: every key\n"
      "duration: 3.5\n"
      "world: {gravity: [0.5, -9.81]}\n"
      "sim: {integrator: midpoint, dt: 0.002}\n"
      "bodies:\n"
      "  - name: bar\n"
      "    shape: {box: [0.2, 4.0]}\n"
      "    mass: 3\n"
      "    inertia: 4\n"
      "    position: [1, -2]\n"
      "    angle: 0.25\n"
      "    velocity: [0.5, 0.75]\n"
      "    angular_velocity: -1.5\n"
      "    color: \"#3b6ea5\"\n"
      "    label: the bar\n"
      "  - name: ground\n"
      "    shape: {circle: 2}\n"
      "    density: 7\n"
      "    static: true\n"
      "forces:\n"
      "  - {type: spring, body: bar, point: [0, 2], anchor: [0, 5], stiffness: 40, rest_length: 0.5, damping: 0.1}\n"
      "  - {type: spring, body: bar, body2: ground, point2: [1, 0], stiffness: 2}\n"
      "  - {type: force, body: bar, point: [0, 1], force: [3, 4], frame: body, from: 0.5, until: 1.5}\n"
      "  - {type: drag, body: bar, linear: 0.25, angular: 0.125}\n"
      "events:\n"
      "  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}\n"
      "  - {time: 1, body: bar, impulse: [0, 1], point: [3, 3], frame: world}\n"
      "expect:\n"
      "  - {time: 1.0, body: bar, velocity: [0.5, 0], angular_velocity: -0.5, tolerance: 1e-12}\n"
      "  - {time: 2.0, momentum: [1, 0], total_energy: 5}\n";
  const sim::scene::SceneDef s = load(text);
  CHECK(s.name == "full");
  CHECK(s.description == "every key");
  CHECK(s.variant.empty());
  CHECK(s.variantNames.empty());
  CHECK(s.duration == 3.5);
  CHECK(s.gravity == sim::core::Vec2(0.5, -9.81));
  CHECK(s.integrator == sim::core::Integrator::Midpoint);
  CHECK(s.dt == 0.002);

  REQUIRE(s.bodies.size() == 2);
  const sim::scene::BodyDef& bar = s.bodies[0];
  CHECK(bar.name == "bar");
  CHECK(bar.shape.kind == sim::core::ShapeKind::Polygon);
  CHECK(bar.shape.vertices.size() == 4);
  CHECK(sim::core::areaProperties(bar.shape).area == doctest::Approx(0.8));
  CHECK(bar.mass == 3.0);
  CHECK(bar.inertia == 4.0);
  CHECK_FALSE(bar.density.has_value());
  CHECK(bar.position == sim::core::Vec2(1, -2));
  CHECK(bar.angle == 0.25);
  CHECK(bar.velocity == sim::core::Vec2(0.5, 0.75));
  CHECK(bar.angularVelocity == -1.5);
  CHECK_FALSE(bar.isStatic);
  const sim::scene::BodyDef& ground = s.bodies[1];
  CHECK(ground.shape.kind == sim::core::ShapeKind::Circle);
  CHECK(ground.shape.radius == 2.0);
  CHECK(ground.density == 7.0);
  CHECK_FALSE(ground.mass.has_value());
  CHECK(ground.isStatic);
  CHECK(s.bodyIndex("ground") == 1);
  CHECK(s.bodyIndex("nope") == -1);

  REQUIRE(s.springs.size() == 2);
  CHECK(s.springs[0].body == "bar");
  CHECK(s.springs[0].body2.empty());
  CHECK(s.springs[0].point == sim::core::Vec2(0, 2));
  CHECK(s.springs[0].anchor == sim::core::Vec2(0, 5));
  CHECK(s.springs[0].stiffness == 40.0);
  CHECK(s.springs[0].restLength == 0.5);
  CHECK(s.springs[0].damping == 0.1);
  CHECK(s.springs[1].body2 == "ground");
  CHECK(s.springs[1].point2 == sim::core::Vec2(1, 0));
  CHECK(s.springs[1].restLength == 0.0);
  REQUIRE(s.pointForces.size() == 1);
  CHECK(s.pointForces[0].force == sim::core::Vec2(3, 4));
  CHECK(s.pointForces[0].point == sim::core::Vec2(0, 1));
  CHECK(s.pointForces[0].bodyFrame);
  CHECK(s.pointForces[0].from == 0.5);
  CHECK(s.pointForces[0].until == 1.5);
  REQUIRE(s.drags.size() == 1);
  CHECK(s.drags[0].linear == 0.25);
  CHECK(s.drags[0].angular == 0.125);

  REQUIRE(s.events.size() == 2);
  CHECK(s.events[0].time == 0.5);
  CHECK(s.events[0].body == "bar");
  CHECK(s.events[0].impulse == sim::core::Vec2(1, 0));
  CHECK(s.events[0].point == sim::core::Vec2(0, 2));
  CHECK_FALSE(s.events[0].pointInWorld);
  CHECK(s.events[1].pointInWorld);

  REQUIRE(s.expects.size() == 2);
  CHECK(s.expects[0].body == "bar");
  CHECK(s.expects[0].velocity == sim::core::Vec2(0.5, 0));
  CHECK(s.expects[0].angularVelocity == -0.5);
  CHECK_FALSE(s.expects[0].position.has_value());
  CHECK(s.expects[0].tolerance == 1e-12);
  CHECK(s.expects[0].loc.line == 30);
  CHECK(s.expects[0].loc.column == 5);
  CHECK(s.expects[1].body.empty());
  CHECK(s.expects[1].momentum == sim::core::Vec2(1, 0));
  CHECK(s.expects[1].totalEnergy == 5.0);
  CHECK(s.expects[1].tolerance == 1e-9);  // the default
}

TEST_CASE("defaults: name from the file stem, dt 0.001, symplectic Euler, no gravity") {
  const sim::scene::SceneDef s = load(kOneBody);
  CHECK(s.name == "inline");
  CHECK(s.description.empty());
  CHECK(s.duration == 1.0);
  CHECK(s.dt == 0.001);
  CHECK(s.integrator == sim::core::Integrator::SymplecticEuler);
  CHECK(s.gravity == sim::core::Vec2::Zero());
  CHECK(s.variant.empty());
  CHECK(s.variantNames.empty());
  REQUIRE(s.bodies.size() == 1);
  const sim::scene::BodyDef& a = s.bodies[0];
  CHECK_FALSE(a.mass.has_value());
  CHECK_FALSE(a.inertia.has_value());
  CHECK_FALSE(a.density.has_value());
  CHECK(a.position == sim::core::Vec2::Zero());
  CHECK(a.velocity == sim::core::Vec2::Zero());
  CHECK(a.angle == 0.0);
  CHECK(a.angularVelocity == 0.0);
  CHECK_FALSE(a.isStatic);
  CHECK(s.events.empty());
  CHECK(s.expects.empty());
  CHECK(s.springs.empty());
  CHECK(s.pointForces.empty());
  CHECK(s.drags.empty());
  // an empty sim: map changes nothing
  const sim::scene::SceneDef t = load("sim: {}\nworld: {}\n" + kOneBody);
  CHECK(t.dt == 0.001);
  CHECK(t.integrator == sim::core::Integrator::SymplecticEuler);
  // the stem drops the directory and .yml too
  CHECK(sim::yaml::loadSceneText(kOneBody, "some/dir/ramp.yml").name == "ramp");
}

TEST_CASE("the model reads its own keys: another layer's key is unknown unless that layer is named") {
  const std::string text = "bodies:\n  - {name: a, shape: {circle: 1}, color: \"#112233\"}\nrender: {fps: 30}\n";
  // the renderer reads `color` and `render`; the model alone rejects them, naming the key
  try {
    (void)sim::yaml::loadSceneText(text, scene_errors::kInlineFile);
    FAIL_CHECK("the scene loaded; expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.line == 3);
    CHECK(e.message.find("unknown key 'render' in the scene") != std::string::npos);
  }
  try {
    (void)sim::yaml::readModel(sim::yaml::sceneSourceText(text, scene_errors::kInlineFile), {{"render"}, {}});
    FAIL_CHECK("the scene loaded; expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.line == 2);
    CHECK(e.message.find("unknown key 'color' in a body") != std::string::npos);
  }
  const sim::scene::SceneDef s =
      sim::yaml::readModel(sim::yaml::sceneSourceText(text, scene_errors::kInlineFile), {{"render"}, {"color"}});
  CHECK(s.bodies.size() == 1);
}

// ---------------------------------------------------------------------------------------------
// variants

TEST_CASE("variantNames lists the variants in file order") {
  const sim::scene::SceneDef base = load(kVariantScene);
  CHECK(base.variantNames == std::vector<std::string>{"zeta", "alpha", "empty"});
  CHECK(base.variant.empty());
  CHECK(load(kVariantScene, "alpha").variantNames == std::vector<std::string>{"zeta", "alpha", "empty"});
}

TEST_CASE("the base scene is not changed by its variants") {
  const sim::scene::SceneDef s = load(kVariantScene);
  CHECK(s.dt == 0.01);
  CHECK(s.duration == 2.0);
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].mass == 3.0);
  REQUIRE(s.events.size() == 2);
}

TEST_CASE("a variant deep-merges: maps key by key, bodies by name, other lists whole") {
  const sim::scene::SceneDef s = load(kVariantScene, "zeta");
  CHECK(s.variant == "zeta");
  CHECK(s.name == "merged");
  CHECK(s.duration == 2.0);
  // sim: key by key: dt changed, integrator kept
  CHECK(s.dt == 0.001);
  CHECK(s.integrator == sim::core::Integrator::Rk4);
  CHECK(s.gravity == sim::core::Vec2(0, -9.81));
  // bodies by name: a changes only the keys given, b untouched, c appended
  REQUIRE(s.bodies.size() == 3);
  const sim::scene::BodyDef& a = s.bodies[0];
  CHECK(a.name == "a");
  CHECK(a.mass == 6.0);
  CHECK(a.velocity == sim::core::Vec2(4, 5));
  CHECK(a.position == sim::core::Vec2(1, 2));
  CHECK(a.friction == 0.25);
  CHECK(a.shape.kind == sim::core::ShapeKind::Polygon);
  CHECK(sim::core::areaProperties(a.shape).area == doctest::Approx(2.0));
  CHECK(s.bodies[1].name == "b");
  CHECK(s.bodies[1].shape.radius == 0.5);
  CHECK(s.bodies[2].name == "c");
  CHECK(s.bodies[2].shape.radius == 1.0);
  CHECK(s.bodies[2].position == sim::core::Vec2(7, 8));
  // events: replaced whole
  REQUIRE(s.events.size() == 1);
  CHECK(s.events[0].time == 1.5);
  CHECK(s.events[0].body == "c");
  CHECK(s.events[0].impulse == sim::core::Vec2(2, 0));
}

TEST_CASE("a variant with other changes, and an empty variant") {
  const sim::scene::SceneDef alpha = load(kVariantScene, "alpha");
  CHECK(alpha.variant == "alpha");
  CHECK(alpha.gravity == sim::core::Vec2::Zero());
  CHECK(alpha.duration == 3.0);
  CHECK(alpha.dt == 0.01);
  CHECK(alpha.bodies.size() == 2);
  CHECK(alpha.events.size() == 2);

  const sim::scene::SceneDef empty = load(kVariantScene, "empty");
  CHECK(empty.variant == "empty");
  CHECK(empty.dt == 0.01);
  CHECK(empty.bodies.size() == 2);
  CHECK(empty.events.size() == 2);
}

TEST_CASE("a variant replaces a body's key whole, so it can change a body's shape") {
  const sim::scene::SceneDef s = load(kOneBody + "variants:\n  boxed:\n    bodies: [{name: a, shape: {box: [2, 3]}}]\n", "boxed");
  REQUIRE(s.bodies.size() == 1);
  CHECK(s.bodies[0].shape.kind == sim::core::ShapeKind::Polygon);
  CHECK(sim::core::areaProperties(s.bodies[0].shape).area == doctest::Approx(6.0));
}

TEST_CASE("an error in a variant's changes is reported at its line in the variant") {
  const std::string scene = kOneBody + "variants:\n";  // the variants start on line 5
  // a value of an existing body
  EXPECT_SCENE_ERROR(scene + "  v:\n    bodies:\n      - {name: a, mass: -2}\n", 7, 25,
                     {"'mass' must be a positive finite number"}, "v");
  // a value in a map the base does not have
  EXPECT_SCENE_ERROR(scene + "  v:\n    sim: {dt: 0}\n", 6, 15, {"'dt' must be a positive finite number"}, "v");
  // a value in a map the base has
  EXPECT_SCENE_ERROR("sim: {integrator: rk4, dt: 0.01}\n" + scene + "  v:\n    sim: {dt: .nan}\n", 7, 15, {"'dt' must be"}, "v");
  // a new body appended by the variant
  EXPECT_SCENE_ERROR(scene + "  v:\n    bodies:\n      - {name: b, shape: {circle: 1}, desity: 2}\n", 7, 39,
                     {"unknown key 'desity'", "did you mean 'density'"}, "v");
  // a new body without a name
  EXPECT_SCENE_ERROR(scene + "  v:\n    bodies:\n      - {shape: {circle: 1}}\n", 7, 9, {"every body needs 'name'"}, "v");
  // a whole list replaced
  EXPECT_SCENE_ERROR(scene + "  v:\n    events:\n      - {time: 0.5, body: nobody, impulse: [1, 0]}\n", 7, 27,
                     {"no body named 'nobody'"}, "v");
  // a map the base does not have, with an unknown key
  EXPECT_SCENE_ERROR(scene + "  v:\n    world: {gravty: [0, 1]}\n", 6, 13, {"unknown key 'gravty'", "did you mean 'gravity'"},
                     "v");
}

// Misspelled keys that a variant adds to a map the base already has (the scene itself, an existing
// map such as sim:, an existing body) must be reported at the variant's line too, not at 1:1.
TEST_CASE("an unknown key a variant adds to an existing map is reported at its line in the variant") {
  const std::string scene = "sim: {integrator: rk4}\n" + kOneBody + "variants:\n";  // the variants start on line 6
  EXPECT_SCENE_ERROR(scene + "  v:\n    durtion: 3\n", 7, 5, {"unknown key 'durtion'", "did you mean 'duration'"}, "v");
  EXPECT_SCENE_ERROR(scene + "  v:\n    sim: {intgrator: midpoint}\n", 7, 11,
                     {"unknown key 'intgrator'", "did you mean 'integrator'"}, "v");
  EXPECT_SCENE_ERROR(scene + "  v:\n    bodies:\n      - {name: a, desity: 2}\n", 8, 19,
                     {"unknown key 'desity'", "did you mean 'density'"}, "v");
}

// ---------------------------------------------------------------------------------------------
// files

TEST_CASE("loadSceneFile: a missing file is a SceneError that says it cannot open it") {
  const std::string path = "/nonexistent-dir/no_such_scene.yaml";
  try {
    (void)sim::yaml::loadSceneFile(path);
    FAIL("loaded a file that does not exist");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.file == path);
    CHECK(e.line == 0);
    CHECK(e.message.find("cannot open") != std::string::npos);
    CHECK(std::string(e.what()).starts_with(path + ": cannot open"));
  }
}

TEST_CASE("loadSceneFile: a file loads, named after its stem, with positions in that file") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("scene_yaml_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct RemoveOnExit {
    fs::path dir;
    ~RemoveOnExit() { fs::remove_all(dir); }
  } cleanup{dir};
  const fs::path good = dir / "my_scene.yaml";
  const fs::path bad = dir / "bad.yaml";
  const fs::path variants = dir / "variants.yaml";
  std::ofstream(good) << kOneBody;
  std::ofstream(variants) << kVariantScene;
  std::ofstream(bad) << kOneBody << "    mass: 0\n";
  CHECK(sim::yaml::loadSceneFile(good.string()).name == "my_scene");
  const sim::scene::SceneDef s = sim::yaml::loadSceneFile(variants.string(), "zeta");
  CHECK(s.name == "merged");
  CHECK(s.variant == "zeta");
  CHECK(s.bodies.size() == 3);
  CHECK(sim::yaml::loadSceneFile(variants.string()).variantNames.size() == 3);
  try {
    (void)sim::yaml::loadSceneFile(bad.string());
    FAIL_CHECK("loaded a bad scene");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.file == bad.string());
    CHECK(e.line == 4);
    CHECK(e.column == 11);
  }
}

TEST_CASE("duplicate keys, a misspelled force type key, and a directory are reported, not ignored") {
  EXPECT_SCENE_ERROR("bodies:\n  - name: a\n    shape: {circle: 1}\n    mass: 1\n    mass: -1\n", 5, 5, {"duplicate key 'mass'"});
  EXPECT_SCENE_ERROR(kOneBody + "bodies: []\n", 4, 1, {"duplicate key 'bodies'"});
  EXPECT_SCENE_ERROR(kOneBody + "forces: [{tpye: spring, body: a, anchor: [0, 0], stiffness: 1}]\n", 4, 11,
                     {"unknown key 'tpye'", "did you mean 'type'"});
  try {
    sim::yaml::loadSceneFile("/tmp");
    FAIL("a directory loaded as a scene");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.message.find("is a directory") != std::string::npos);
  }
}

TEST_CASE("booleans take the YAML 1.1 spellings in any case") {
  const sim::scene::SceneDef s =
      sim::yaml::loadSceneText("bodies: [{name: a, shape: {circle: 1}, static: True}]\n", "inline.yaml");
  CHECK(s.bodies[0].isStatic);
}

TEST_CASE("scene and variant names must be one plain path component, at their key") {
  expectSceneError("name: ../escaped\nbodies: [{name: a, shape: {box: [1, 1]}}]\n", 1, 7,
                   {"the scene's name '../escaped'", "starts with '.'"});
  expectSceneError("name: \"\"\nbodies: [{name: a, shape: {box: [1, 1]}}]\n", 1, 7, {"is empty"});
  expectSceneError("bodies: [{name: a, shape: {box: [1, 1]}}]\nvariants:\n  a/b: {duration: 2}\n", 3, 3,
                   {"variant name 'a/b'", "contains '/'"});
}

TEST_CASE("a run of more steps than max_steps is refused at dt, or at duration, saying what to change") {
  expectSceneError("duration: 1.0e6\nsim: {dt: 1.0e-12}\nbodies: [{name: a, shape: {box: [1, 1]}}]\n", 2, 11,
                   {"the run needs 1e+18 steps", "more than the limit of 1e+08", "raise dt", "max_steps"});
  expectSceneError("duration: 1.0e6\nbodies: [{name: a, shape: {box: [1, 1]}}]\n", 1, 11, {"1e+09 steps"});
  // the scene that needs them says so
  const auto def = sim::yaml::loadSceneText(
      "duration: 1.0e6\nsim: {max_steps: 1.0e9}\nbodies: [{name: a, shape: {box: [1, 1]}}]\n", scene_errors::kInlineFile);
  CHECK(def.maxSteps == 1e9);
}

TEST_CASE("a duplicate body name among many is found at its line (by hash, not by scan)") {
  std::string text = "bodies:\n";
  for (int k = 0; k < 2000; ++k) text += "  - {name: b" + std::to_string(k) + ", shape: {circle: 0.1}}\n";
  text += "  - {name: b1234, shape: {circle: 0.1}}\n";
  expectSceneError(text, 2002, 0, {"duplicate body name 'b1234'"});
}

// ---------------------------------------------------------------------------------------------
// bodies made of parts

TEST_CASE("a body of parts: too few parts, overlapping parts, a static one and unknown keys are refused at their line") {
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: a\n"
      "    shape: {compound: [{box: [1, 1]}]}\n",
      3, 0, {"at least two", "center_of_mass"});
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: a\n"
      "    shape:\n"
      "      compound:\n"
      "        - {box: [1, 1]}\n"
      "        - {box: [1, 1], position: [2, 0]}\n"
      "        - {circle: 0.5, position: [0.9, 0]}\n",
      7, 11, {"overlaps an earlier part", "may touch"});
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: a\n"
      "    shape: {compound: [{box: [1, 1]}, {box: [1, 1], position: [1, 0]}]}\n"
      "    static: true\n",
      4, 0, {"static body cannot be made of parts"});
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: a\n"
      "    shape: {compound: [{box: [1, 1], mass: 2}, {box: [1, 1], position: [1, 0]}]}\n",
      3, 0, {"mass"});
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: a\n"
      "    shape: {compound: [{box: [1, 1], circle: 1}, {box: [1, 1], position: [1, 0]}]}\n",
      3, 0, {"exactly one of box, polygon or circle"});
  EXPECT_SCENE_ERROR(
      "sim: {max_parts: 2}\n"
      "bodies:\n"
      "  - name: a\n"
      "    shape: {compound: [{box: [1, 1]}, {box: [1, 1], position: [1, 0]}, {box: [1, 1], position: [2, 0]}]}\n",
      4, 0, {"3 parts", "max_parts"});
  // parts that touch are one body
  CHECK(load("bodies:\n"
             "  - name: a\n"
             "    shape: {compound: [{box: [1, 1]}, {box: [1, 1], position: [1, 0]}]}\n")
            .bodies[0]
            .shape.parts.size() == 2);
}

TEST_CASE("center_of_mass is a point [x, y], and a plane has none") {
  EXPECT_SCENE_ERROR(kOneBody + "    center_of_mass: 3\n", 4, 0, {"center_of_mass"});
  EXPECT_SCENE_ERROR(
      "bodies:\n"
      "  - name: f\n"
      "    shape: {plane: {point: [0, 0], normal: [0, 1]}}\n"
      "    center_of_mass: [0, 1]\n",
      4, 0, {"a plane has no 'center_of_mass'"});
  CHECK(load(kOneBody + "    center_of_mass: [0.5, 0]\n").bodies[0].centerOfMass == sim::core::Vec2(0.5, 0));
}

TEST_CASE("sim: recycle is soft_step's, on, off or with its distance") {
  EXPECT_SCENE_ERROR("sim: {recycle: true}\n" + kOneBody, 1, 16, {"'recycle'", "soft_step", "'collisions: auto'"});
  EXPECT_SCENE_ERROR("sim: {collisions: sequential, recycle: true}\n" + kOneBody, 1, 40, {"'collisions: sequential'"});
  EXPECT_SCENE_ERROR("sim: {collisions: soft_step, recycle: {distance: -1}}\n" + kOneBody, 1, 0, {"distance"});
  EXPECT_SCENE_ERROR("sim: {collisions: soft_step, recycle: {angle: 3}}\n" + kOneBody, 1, 0, {"angle"});
  CHECK(load("sim: {collisions: soft_step, recycle: true}\n" + kOneBody).recycleDistance ==
        sim::core::settings::kRecycleDistance);
  CHECK(load("sim: {collisions: soft_step, recycle: {distance: 0.01}}\n" + kOneBody).recycleDistance == 0.01);
  CHECK(load("sim: {collisions: sequential, recycle: false}\n" + kOneBody).recycleDistance == 0.0);
}

TEST_CASE("a static body has no center_of_mass to move") {
  EXPECT_SCENE_ERROR(kOneBody + "    static: true\n    center_of_mass: [0.5, 0]\n", 5, 0, {"static body", "center_of_mass"});
}

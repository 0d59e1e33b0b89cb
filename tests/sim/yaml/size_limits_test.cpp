// The bounds on a scene's size (sim/yaml/size_limits.h): bodies and polygon vertices past the
// default are refused at their list with the key that raises the bound, and that key raises it.
#include "sim/yaml/size_limits.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/yaml/scene_yaml.h"
#include "support/scene_error_check.h"

namespace {

const char* const kFile = "inline.yaml";

void expectSceneError(const std::string& text, int line, int column, std::initializer_list<std::string> words) {
  scene_errors::expectSceneError(
      [](const std::string& t, const std::string& f, const std::string& v) { return sim::yaml::loadSceneText(t, f, v); }, kFile,
      text, line, column, words, "");
}

// `n` circles apart on the x axis, the list starting on line `first`
std::string circles(int n) {
  std::string s = "bodies:\n";
  for (int k = 0; k < n; ++k)
    s += "  - {name: b" + std::to_string(k) + ", shape: {circle: 0.1}, position: [" + std::to_string(k) + ", 0]}\n";
  return s;
}

// a regular polygon of `n` vertices on the unit circle, as a flow list
std::string polygon(int n) {
  std::string s = "[";
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / n;
    s += (k ? ", [" : "[") + std::to_string(std::cos(a)) + ", " + std::to_string(std::sin(a)) + "]";
  }
  return s + "]";
}

}  // namespace

TEST_CASE("bodies past max_bodies are refused at the list, naming the key; the key raises the bound") {
  expectSceneError("sim: {max_bodies: 2}\n" + circles(3), 3, 3,
                   {"the scene has 3 bodies, more than the limit of 2", "'sim: {max_bodies: N}'"});
  CHECK(sim::yaml::loadSceneText("sim: {max_bodies: 3}\n" + circles(3), kFile).bodies.size() == 3);
  expectSceneError("sim: {max_bodies: 0}\n" + circles(1), 1, 19, {"'max_bodies' must be a whole number from 1"});
  expectSceneError("sim: {max_bodies: 2.5}\n" + circles(1), 1, 19, {"'max_bodies' must be a whole number"});
}

TEST_CASE("the default bounds are the documented ones") {
  const sim::yaml::SizeLimits limits;
  CHECK(limits.maxBodies == 100000);
  CHECK(limits.maxVertices == 1024);
  CHECK(limits.maxEntries == 1000000);
}

TEST_CASE("forces, events and expect entries together past max_entries are refused at the list that passes it") {
  const std::string scene = circles(2) +
                            "forces: [{type: force, body: b0, force: [1, 0]}]\n"
                            "events: [{time: 0.1, body: b1, impulse: [1, 0]}]\n"
                            "expect: [{time: 0.5, body: b0, position: [0, 0], tolerance: 10}]\n";
  // the lists start on lines 5, 6 and 7: with a limit of 2 the expect list is the one that passes it
  expectSceneError(
      "sim: {max_entries: 2}\n" + scene, 7, 9,
      {"forces, events and expect entries number 3 up to this list, more than the limit of 2", "'sim: {max_entries: N}'"});
  expectSceneError("sim: {max_entries: 1}\n" + scene, 6, 9, {"number 2 up to this list"});
  const sim::scene::SceneDef def = sim::yaml::loadSceneText("sim: {max_entries: 3}\n" + scene, kFile);
  CHECK(def.pointForces.size() + def.events.size() + def.expects.size() == 3);
}

TEST_CASE("a polygon past max_vertices is refused at its list; the key raises the bound") {
  const std::string body = "bodies:\n  - {name: a, shape: {polygon: ";
  CHECK(sim::yaml::loadSceneText(body + polygon(1024) + "}}\n", kFile).bodies.front().shape.vertices.size() == 1024);
  expectSceneError(body + polygon(1025) + "}}\n", 2, 32,
                   {"a polygon of 1025 vertices, more than the limit of 1024", "'sim: {max_vertices: N}'"});
  CHECK(sim::yaml::loadSceneText("sim: {max_vertices: 1025}\n" + body + polygon(1025) + "}}\n", kFile)
            .bodies.front()
            .shape.vertices.size() == 1025);
}

// A variant merged over its scene: on new maps and lists, never changing a node of the file (so an
// alias keeps what it was written as, and a map merged into itself is no hazard), each key given
// once, and bounded by the file's size however aliases repeat what they name.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "sim/yaml/scene_source.h"
#include "sim/yaml/scene_yaml.h"

namespace {

const char* const kFile = "inline.yaml";

// the SceneError that loading `text` with `variant` throws (its message empty when none is thrown)
sim::yaml::SceneError loadError(const std::string& text, const std::string& variant) {
  try {
    (void)sim::yaml::loadSceneText(text, kFile, variant);
  } catch (const sim::yaml::SceneError& e) {
    return e;
  }
  return {kFile, 0, 0, ""};
}

const std::string kOneBody = "name: s\nbodies: [{name: a, shape: {box: [1, 1]}}]\n";

// `{k0: &m<depth-1> {...}, k1: *m<depth-1>, ..., k9: *m<depth-1>}`: ten times more values per level
// once expanded, written in about 50 bytes a level
std::string aliasTree(int depth) {
  std::string tree = "{k: 1}";
  for (int level = 1; level <= depth; ++level) {
    // not "m" + std::to_string(...): g++ 12 warns of overlapping copies there (GCC bug 105329)
    const std::string anchor = std::string(1, 'm') += std::to_string(level - 1);
    std::string next = "{k0: &";
    next += anchor;
    next += ' ';
    next += tree;
    for (int k = 1; k < 10; ++k) next += ", k" + std::to_string(k) + ": *" + anchor;
    tree = next + '}';
  }
  return tree;
}

}  // namespace

TEST_CASE("a key given twice in a variant is an error at its second place, not a merge of a map into itself") {
  // the fuzzer's use-after-free: the second `a` merged the map `m` into itself, inserting the null
  // key (never found by name) into the map being iterated
  const sim::yaml::SceneError e =
      loadError(kOneBody + "world: {}\nvariants:\n  v:\n    world: {a: &m {~: 1, b: 2}, a: *m}\n", "v");
  CHECK(e.line == 6);
  CHECK(e.column == 33);
  CHECK(e.message == "duplicate key 'a' in variant 'v'; give each key once");
}

TEST_CASE("duplicate keys in a variant are errors at every level, as they are in the scene") {
  CHECK(loadError(kOneBody + "variants:\n  v: {duration: 1, duration: 2}\n", "v").message ==
        "duplicate key 'duration' in variant 'v'; give each key once");
  const sim::yaml::SceneError nested =
      loadError(kOneBody + "sim: {dt: 0.01}\nvariants:\n  v:\n    sim: {dt: 0.1, dt: 0.2}\n", "v");
  CHECK(nested.line == 6);
  CHECK(nested.column == 20);
  CHECK(nested.message.find("duplicate key 'dt'") == 0);
  const sim::yaml::SceneError body =
      loadError(kOneBody + "variants:\n  v:\n    bodies: [{name: a, mass: 2}, {name: a, mass: 3}]\n", "v");
  CHECK(body.line == 5);
  CHECK(body.message == "body 'a' is changed twice in variant 'v'; give its changes once");
}

TEST_CASE("a variant that names a map of the scene through its alias merges it with itself, unchanged") {
  const std::string text = kOneBody + "world: &w {gravity: [0, -2], friction: 0.5}\nvariants:\n  v: {world: *w}\n";
  const sim::yaml::SceneSource s = sim::yaml::sceneSourceText(text, kFile, "v");
  REQUIRE(s.root["world"].IsMap());
  CHECK(s.root["world"].size() == 2);
  CHECK(s.root["world"]["gravity"][1].as<double>() == -2.0);
  // a key that is not a name (here the null key ~, which no lookup by name finds) is an error at it
  const sim::yaml::SceneError e = loadError(kOneBody + "world: &w {gravity: [0, -2], ~: 1}\nvariants:\n  v: {world: *w}\n", "v");
  CHECK(e.line == 3);
  CHECK(e.column == 30);
  CHECK(e.message == "a key in variant 'v' must be a name, got nothing");
}

TEST_CASE("a variant changes the body it names, not the bodies that share an alias with it") {
  const std::string text =
      "bodies:\n"
      "  - {name: a, shape: &s {circle: 1}, velocity: &v [1, 0]}\n"
      "  - {name: b, shape: *s, velocity: *v, position: [5, 0]}\n"
      "variants:\n"
      "  v: {bodies: [{name: a, shape: {circle: 2}, velocity: [3, 0]}]}\n";
  const sim::scene::SceneDef s = sim::yaml::loadSceneText(text, kFile, "v");
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].shape.radius == 2.0);
  CHECK(s.bodies[0].velocity.x() == 3.0);
  CHECK(s.bodies[1].shape.radius == 1.0);
  CHECK(s.bodies[1].velocity.x() == 1.0);
  // and the base scene read from the same text is the base scene
  const sim::scene::SceneDef base = sim::yaml::loadSceneText(text, kFile);
  CHECK(base.bodies[0].shape.radius == 1.0);
}

TEST_CASE("a variant whose aliases repeat a tree tenfold per level stops at the file's size") {
  // 10^7 pairs once expanded, from under 400 bytes
  const std::string text = kOneBody + "world: &w " + aliasTree(7) + "\nvariants:\n  v: {world: *w}\n";
  const sim::yaml::SceneError e = loadError(text, "v");
  CHECK(e.line > 0);
  CHECK(e.message.find("variant 'v' repeats its values through aliases") == 0);
  // a tree of aliases that the merge does not walk is left whole: the model's reader names its key
  const sim::yaml::SceneError unknown = loadError(kOneBody + "variants:\n  v: {world: " + aliasTree(7) + "}\n", "v");
  CHECK(unknown.message.find("unknown key 'k0' in world") == 0);
}

TEST_CASE("a variant whose aliases nest maps past the parser's depth is refused, not a stack overflow") {
  // a chain of 5,000 maps, each one the next's value through an alias: 5,000 levels from text that
  // nests two, and a merge of the chain with itself walks them all
  std::string text = kOneBody + "chain:\n  c0: &a0 {k: 1}\n";
  for (int i = 1; i < 5000; ++i)
    text += "  c" + std::to_string(i) + ": &a" + std::to_string(i) + " {k: *a" + std::to_string(i - 1) + "}\n";
  text += "loop: *a4999\nvariants:\n  v: {loop: *a4999}\n";
  const sim::yaml::SceneError e = loadError(text, "v");
  CHECK(e.line == 4504);  // c4500, where the map 501 levels down is written
  CHECK(e.message.find("variant 'v' nests its maps more than 500 levels deep through aliases") == 0);
}

TEST_CASE("text the parser cannot start a document with is invalid YAML at its place, not a second document") {
  const sim::yaml::SceneError comma = loadError("\n# a comment\n,a: 1\n", "");
  CHECK(comma.line == 3);
  CHECK(comma.column == 1);
  CHECK(comma.message.find("invalid YAML: a scene cannot start with ','") == 0);
  // a '---' or a '...' line does start a second one
  const sim::yaml::SceneError dashes = loadError(kOneBody + "---\nname: t\n", "");
  CHECK(dashes.line == 3);
  CHECK(dashes.message.find("a second YAML document") == 0);
  const sim::yaml::SceneError dots = loadError(kOneBody + "... # end\n  # next\nname: t\n", "");
  CHECK(dots.line == 5);
  CHECK(dots.message.find("a second YAML document") == 0);
  // a byte order mark is not counted in the parser's places, and is skipped here too
  const sim::yaml::SceneError bom = loadError("\xEF\xBB\xBF" + kOneBody + "---\nname: t\n", "");
  CHECK(bom.line == 3);
  CHECK(bom.message.find("a second YAML document") == 0);
  const sim::yaml::SceneError bomComma = loadError("\xEF\xBB\xBF,a: 1\n", "");
  CHECK(bomComma.message.find("invalid YAML: a scene cannot start with ','") == 0);
}

TEST_CASE("a variant keeps the scene's order of keys and bodies, and appends what it adds") {
  const std::string text =
      kOneBody +
      "sim: {dt: 0.01, integrator: rk4}\nvariants:\n"
      "  v: {sim: {collisions: none, dt: 0.02}, bodies: [{name: c, shape: {circle: 1}}, {name: a, mass: 2}]}\n";
  const sim::yaml::SceneSource s = sim::yaml::sceneSourceText(text, kFile, "v");
  std::string keys;
  for (const auto& kv : s.root["sim"]) keys += kv.first.Scalar() + " ";
  CHECK(keys == "dt integrator collisions ");
  CHECK(s.root["sim"]["dt"].as<double>() == 0.02);
  REQUIRE(s.root["bodies"].size() == 2);
  CHECK(s.root["bodies"][0]["name"].Scalar() == "a");
  CHECK(s.root["bodies"][0]["mass"].as<double>() == 2.0);
  CHECK(s.root["bodies"][1]["name"].Scalar() == "c");
}

TEST_CASE("a file larger than the limit is refused after reading at most the limit") {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("rigidreel-big-" + std::to_string(::getpid()) + ".yaml")).string();
  std::ofstream(path) << "name: big\n";
  std::filesystem::resize_file(path, (17u << 20));
  try {
    (void)sim::yaml::readSceneSource(path);
    FAIL_CHECK("17 MiB loaded");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(std::string(e.what()).find(path) == 0);
    CHECK(e.message.find("larger than the limit of 16 MiB") != std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST_CASE("a device, a FIFO or a folder is refused before it is opened") {
  const std::string fifo =
      (std::filesystem::temp_directory_path() / ("rigidreel-fifo-" + std::to_string(::getpid()) + ".yaml")).string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // no structured binding: clang 14 cannot capture one in CAPTURE (make sanitize builds with it)
  for (const auto& [pathBound, whatBound] :
       std::vector<std::pair<std::string, std::string>>{{"/dev/zero", "is a device, not a regular file"},
                                                        {fifo, "is a FIFO (named pipe), not a regular file"},
                                                        {std::filesystem::temp_directory_path().string(), "is a directory"}}) {
    const std::string path = pathBound, what = whatBound;
    CAPTURE(path);
    try {
      (void)sim::yaml::readSceneSource(path);
      FAIL_CHECK("loaded");
    } catch (const sim::yaml::SceneError& e) {
      CHECK(e.message.find(what) == 0);
    }
  }
  std::filesystem::remove(fifo);
}

TEST_CASE("every variant merged from one parse of the file sees the file, not another variant's changes") {
  const std::string text =
      "render: &r {trails: true}\n"
      "bodies:\n"
      "  - {name: a, shape: {circle: 1}, position: [0, 0]}\n"
      "variants:\n"
      "  v: {bodies: [{name: a, position: [1, 2]}], render: *r, duration: 3}\n"
      "  w: {}\n";
  const sim::yaml::SceneDocument d = sim::yaml::sceneDocumentText(text, kFile);
  CHECK(d.variantNames == std::vector<std::string>{"v", "w"});
  CHECK(d.dimensions == 2);
  const sim::yaml::SceneSource v = sim::yaml::sceneSource(d, "v");
  CHECK(v.root["bodies"][0]["position"][0].as<double>() == 1.0);
  CHECK(v.root["duration"].as<double>() == 3.0);
  // the variant after it, and the base, read the file as written
  for (const std::string& name : {std::string("w"), std::string()}) {
    CAPTURE(name);
    const sim::yaml::SceneSource s = sim::yaml::sceneSource(d, name);
    CHECK(s.root["bodies"][0]["position"][0].as<double>() == 0.0);
    CHECK(!s.root["duration"]);
  }
  CHECK(!d.root["duration"]);
}

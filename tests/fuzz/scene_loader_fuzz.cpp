// libFuzzer target: the `check` path on any bytes. Load the scene (parse, merge each variant, read
// every key), build its world and run a few steps. A SceneError or a refusal of the world is the
// expected answer to bad input; anything else (a crash, a sanitizer report, another exception, a
// hang past libFuzzer's timeout) is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_error.h"
#include "sim/yaml/scene_yaml.h"

namespace {

// the first steps of a scene: enough to reach the collision methods, short enough to stay fast
constexpr int kSteps = 20;

void checkOne(const std::string& text, const std::string& variant) {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(text, "fuzz.yaml", variant);
  sim::world::World world = sim::scene::buildWorld(def);
  try {
    world.start();
    world.advanceTo(kSteps * def.dt);
  } catch (const sim::world::InitialOverlap&) {
  } catch (const sim::core::Diverged&) {
  } catch (const std::runtime_error&) {
    // the methods' own refusals (impacts piling up) are answers, not crashes
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const sim::scene::SceneDef base = sim::yaml::loadSceneText(text, "fuzz.yaml");
    checkOne(text, "");
    for (const std::string& v : base.variantNames) checkOne(text, v);
  } catch (const sim::yaml::SceneError&) {}
  return 0;
}

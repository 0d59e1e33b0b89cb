#include "render/cli/scene_file.h"

namespace render::cli {

namespace {

SceneFile read(const sim::yaml::SceneSource& source) {
  SceneFile f;
  f.scene = render::scene::readScene(source, {{render::analysis::kStabilityKey}, {}});
  f.stability = render::analysis::readStability(source, f.scene.model);
  return f;
}

}  // namespace

SceneFile readSceneFile(const std::string& path, const std::string& variant) {
  return read(sim::yaml::readSceneSource(path, variant));
}

SceneFile sceneFileText(const std::string& text, const std::string& file, const std::string& variant) {
  return read(sim::yaml::sceneSourceText(text, file, variant));
}

}  // namespace render::cli

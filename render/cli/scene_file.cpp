#include "render/cli/scene_file.h"

#include "render/analysis/analysis3d.h"

namespace render::cli {

namespace {

SceneFile readSource(const sim::yaml::SceneSource& source) {
  SceneFile f;
  f.scene = render::scene::readScene(source, {{render::analysis::kStabilityKey, render::golden::kGoldenKey}, {}});
  f.stability = render::analysis::readStability(source, f.scene.model);
  f.golden = render::golden::readGolden(source, f.scene.model.duration);
  return f;
}

}  // namespace

SceneFile OpenScene::read(const std::string& variant) const { return readSource(sim::yaml::sceneSource(document_, variant)); }

SceneFile3d OpenScene::read3d(const std::string& variant) const {
  const sim::yaml::SceneSource source = sim::yaml::sceneSource(document_, variant);
  SceneFile3d f;
  f.scene = render::scene3d::readScene(source, {{render::analysis::kStabilityKey, render::golden::kGoldenKey}, {}});
  f.stability = render::analysis::readStability3d(source);
  f.golden = render::golden::readGolden(source, f.scene.model.duration);
  return f;
}

}  // namespace render::cli

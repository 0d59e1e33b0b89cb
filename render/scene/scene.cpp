#include "render/scene/scene.h"

#include "render/scene/render_yaml.h"

namespace render::scene {

Scene readScene(const sim::yaml::SceneSource& source, const sim::yaml::OtherKeys& others) {
  // the model reads its keys and leaves ours alone
  sim::yaml::OtherKeys keys = others;
  keys.scene.emplace_back(kRenderKey);
  keys.scene.insert(keys.scene.end(), kPollKeys.begin(), kPollKeys.end());
  keys.body.insert(keys.body.end(), kBodyKeys.begin(), kBodyKeys.end());
  Scene s;
  s.model = sim::yaml::readModel(source, keys);
  s.render = readRender(source, s.model);
  return s;
}

}  // namespace render::scene

// Inline scenes for the renderer's tests, read as the command line reads a file: the model and how
// to draw it (stability:, the analysis' key, is accepted and left alone).
#pragma once

#include <string>

#include "render/scene/scene.h"
#include "sim/yaml/scene_source.h"

namespace drawn_scene {

inline render::scene::Scene load(const std::string& yaml, const std::string& variant = "",
                                 const std::string& file = "inline.yaml") {
  return render::scene::readScene(sim::yaml::sceneSourceText(yaml, file, variant), {{"stability"}, {}});
}

inline render::scene::Scene loadFile(const std::string& path, const std::string& variant = "") {
  return render::scene::readScene(sim::yaml::readSceneSource(path, variant), {{"stability"}, {}});
}

}  // namespace drawn_scene

// A scene file as the command line reads it: one parse, and each layer's reader for its own keys
// (the model by sim/yaml, the render: block and the bodies' looks by render/scene, stability: by
// the analysis, golden: by render/golden), so every key of the file is checked whatever the command needs of it.
#pragma once

#include <string>

#include "render/analysis/stability_def.h"
#include "render/golden/golden_def.h"
#include "render/scene/scene.h"
#include "render/scene3d/scene.h"

namespace render::cli {

struct SceneFile {
  render::scene::Scene scene;                // the model and how to draw it
  render::analysis::StabilityDef stability;  // what `rigidreel stability` searches
  render::golden::GoldenDef golden;          // what `rigidreel golden` records and how closely it checks

  const sim::scene::SceneDef& model() const { return scene.model; }
  sim::scene::SceneDef& model() { return scene.model; }
  // the model with its stability: block, as the stability search takes it
  render::analysis::Study study() const { return {scene.model, stability}; }
};

// the scene in `path` with the named variant merged in ("" for the base scene); throws
// sim::yaml::SceneError at the fault's FILE:LINE:COL
SceneFile readSceneFile(const std::string& path, const std::string& variant = "");
// the same from text; `file` names it in messages
SceneFile sceneFileText(const std::string& text, const std::string& file, const std::string& variant = "");

// a 3D scene file (`dimensions: 3`), read the same way: its model and look (render/scene3d) and its
// stability: block (dt only)
struct SceneFile3 {
  render::scene3d::Scene scene;
  render::analysis::StabilityDef stability;

  const sim::scene3d::SceneDef& model() const { return scene.model; }
  sim::scene3d::SceneDef& model() { return scene.model; }
};

// whether the scene in `path` is 3D: every command asks first and takes the 3D path for it; throws
// sim::yaml::SceneError for a file that cannot be read
bool isSceneFile3d(const std::string& path);
SceneFile3 readSceneFile3(const std::string& path, const std::string& variant = "");

}  // namespace render::cli

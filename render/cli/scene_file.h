// A scene file as the command line reads it: one parse, and each layer's reader for its own keys
// (the model by sim/yaml, the render: block and the bodies' looks by render/scene, stability: by
// the analysis, golden: by render/golden), so every key of the file is checked whatever the command needs of it.
#pragma once

#include <string>
#include <vector>

#include "render/analysis/stability_def.h"
#include "render/golden/golden_def.h"
#include "render/scene/scene.h"
#include "render/scene3d/scene.h"
#include "sim/yaml/scene_source.h"

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

// a 3D scene file (`dimensions: 3`), read the same way: its model and look (render/scene3d), its
// stability: block (dt only) and its golden: block
struct SceneFile3d {
  render::scene3d::Scene scene;
  render::analysis::StabilityDef stability;
  render::golden::GoldenDef golden;

  const sim::scene3d::SceneDef& model() const { return scene.model; }
  sim::scene3d::SceneDef& model() { return scene.model; }
};

// A scene file read and parsed once: its `dimensions` says which path each subcommand takes, and
// every variant, 2D or 3D, is merged and read from the one parse. A copy shares the parse.
class OpenScene {
 public:
  // throws sim::yaml::SceneError at the fault's FILE:LINE:COL
  explicit OpenScene(const std::string& path) : document_(sim::yaml::readSceneDocument(path)) {}
  OpenScene(const std::string& text, const std::string& file) : document_(sim::yaml::sceneDocumentText(text, file)) {}

  const std::string& path() const { return document_.file; }
  bool is3d() const { return document_.dimensions == 3; }
  const std::vector<std::string>& variantNames() const { return document_.variantNames; }
  // the named variant ("" for the base scene) of a 2D scene, or of a 3D one
  SceneFile read(const std::string& variant = "") const;
  SceneFile3d read3d(const std::string& variant = "") const;

 private:
  sim::yaml::SceneDocument document_;
};

}  // namespace render::cli

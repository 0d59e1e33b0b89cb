// `rigidreel lecture`'s plan of a 3D scene. The pack's list and its jobs read of a plan's scenes
// only their names, durations and render: blocks, which 2D and 3D scenes share; so a 3D scene's plan
// holds those in its (2D) scenes, and its job reads the 3D model again (renderVideos3d, writeSnapshots3d).
#include "render/cli/commands.h"
#include "render/cli/space3d.h"
#include "sim/scene3d/scene_build.h"

namespace render::cli {

namespace {

// what the pack needs of a 3D variant, in the plan's scene
render::scene::Scene outline(const render::scene3d::Scene& scene) {
  render::scene::Scene s;
  s.model.name = scene.model.name;
  s.model.description = scene.model.description;
  s.model.variant = scene.model.variant;
  s.model.variantNames = scene.model.variantNames;
  s.model.duration = scene.model.duration;
  s.render = scene.render;
  return s;
}

}  // namespace

LecturePlan planLecture3d(const std::string& file) {
  const render::scene3d::Scene base = readSceneFile3(file).scene;
  LecturePlan plan{file, outline(base), {}};
  std::vector<std::string> variants = base.model.variantNames;
  if (variants.empty()) variants.push_back("");
  for (const std::string& v : variants) {
    const render::scene3d::Scene scene = v.empty() ? base : readSceneFile3(file, v).scene;
    // every variant's world built once: a body no solid can be is bad input before anything renders
    try {
      (void)sim::scene3d::buildWorld(scene.model);
    } catch (const std::invalid_argument& e) {
      throw sim::yaml::SceneError(file, 0, 0, (v.empty() ? "" : "variant '" + v + "': ") + e.what());
    }
    plan.videos.push_back(outline(scene));
  }
  return plan;
}

}  // namespace render::cli

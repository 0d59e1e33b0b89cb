// The scene files of `rigidreel lecture`: the files its arguments name, and each file's variants
// read as a lecture job reads them, each video's world started (overlapping bodies are bad input
// at their FILE:LINE:COL before anything renders).
#pragma once

#include <string>
#include <vector>

#include "render/cli/scene_file.h"
#include "render/video/render_plan.h"

namespace render::cli {

// the files: a file as given, a directory as every `*.yaml` in it, in its order.txt's order or else
// sorted (scene_order.h); throws UsageError for a path that does not exist and for a directory
// without scenes, sim::yaml::SceneError for a bad order.txt
std::vector<std::string> lectureSceneFiles(const std::vector<std::string>& arguments);

// the file's variants ("" the base scene), each that will be a video (a variant, or the base scene
// when it has none) with its world started; throws sim::yaml::SceneError
render::video::LoadVariant lectureLoader(const OpenScene& file);
// the same for a 3D scene file: each variant's world built (a body no solid can be is bad input
// before anything renders)
render::video::LoadVariant3d lectureLoader3d(const OpenScene& file);

}  // namespace render::cli

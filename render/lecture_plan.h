// What `rigidreel lecture` will do, known before anything renders: the scene files its arguments
// name, each checked (a bad one is a sim::SceneError at its FILE:LINE:COL), and the outputs each
// scene's job writes.
#pragma once

#include <string>
#include <vector>

#include "scene_def.h"

namespace render {

// the files: a file as given, a directory as every `*.yaml` in it, sorted; throws UsageError for
// a path that does not exist and for a directory without scenes
std::vector<std::string> lectureSceneFiles(const std::vector<std::string>& arguments);

struct LecturePlan {
  std::string file;
  sim::SceneDef base;                 // the scene without a variant: its name and its `panels`
  std::vector<sim::SceneDef> videos;  // each variant, or the base scene when it has none
};

// loads the scene and every variant and starts each world once (overlapping bodies are bad input
// too); throws sim::SceneError
LecturePlan planLecture(const std::string& file);

// the paths the scene's job writes under `root`: each video (.mp4) and poster (.png), then each
// panel image; `panels: impacts` needs the runs' impacts, so it simulates (throws sim::Diverged)
std::vector<std::string> lectureOutputs(const LecturePlan& plan, const std::string& root);

}  // namespace render

// What `rigidreel lecture` will do, known before anything renders: the scene files its arguments
// name, each checked (a bad one is a sim::yaml::SceneError at its FILE:LINE:COL), and the outputs each
// scene's job writes.
#pragma once

#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace render::cli {

// the files: a file as given, a directory as every `*.yaml` in it, sorted; throws UsageError for
// a path that does not exist and for a directory without scenes
std::vector<std::string> lectureSceneFiles(const std::vector<std::string>& arguments);

// for a 3D scene (dimensions: 3) the scenes hold its names, durations and render: blocks, all the
// pack reads of them (lecture_plan3d.cpp)
struct LecturePlan {
  std::string file;
  render::scene::Scene base;                 // the scene without a variant: its name and its `panels`
  std::vector<render::scene::Scene> videos;  // each variant, or the base scene when it has none
  size_t mostImpacts = 0;                    // with `panels: impacts`: the most impacts of any video's run
};

// loads the scene and every variant and starts each world once (overlapping bodies are bad input
// too); with `panels: impacts` runs each to count its impacts. Throws sim::yaml::SceneError, sim::world::Diverged
LecturePlan planLecture(const std::string& file);

// the paths the scene's job writes under `root`: each video (.mp4) and poster (.png), then each
// panel image
std::vector<std::string> lectureOutputs(const LecturePlan& plan, const std::string& root);

}  // namespace render::cli

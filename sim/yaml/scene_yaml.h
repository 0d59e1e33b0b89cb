// YAML scene files to SceneDef, with every fault reported as FILE:LINE:COL: message.
// The format is documented key by key in scenes/README.md.
#pragma once

#include <stdexcept>
#include <string>

#include "sim/scene/scene_def.h"

namespace sim::yaml {
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;

// bad input: what() is "FILE:LINE:COL: message" (or "FILE: message" when there is no position)
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, int line, int column, const std::string& message);
  std::string file;
  int line, column;
  std::string message;
};

// the scene in `path`, with the named variant deep-merged over it ("" for the base scene)
SceneDef loadSceneFile(const std::string& path, const std::string& variant = "");
// the same from text; `file` names it in messages
SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant = "");

}  // namespace sim::yaml

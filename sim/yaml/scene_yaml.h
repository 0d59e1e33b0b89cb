// The model of a scene file (what buildWorld needs) read from its YAML tree, with every fault
// reported as FILE:LINE:COL: message. The format is documented key by key in scenes/README.md.
#pragma once

#include <string>

#include "sim/scene/scene_def.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

// keys of the file that other readers read (the renderer's block and per-body keys, the analysis'
// block): the model's reader accepts them as known and leaves them alone
struct OtherKeys {
  Keys scene;  // at the top level
  Keys body;   // in each body
};

// the model of the scene in `source`; any key not the model's nor in `others` is an error that names
// the nearest valid key. Throws SceneError.
sim::scene::SceneDef readModel(const SceneSource& source, const OtherKeys& others = {});

// the model of a file that has nothing but the model: readModel(readSceneSource(path, variant))
sim::scene::SceneDef loadSceneFile(const std::string& path, const std::string& variant = "");
// the same from text; `file` names it in messages
sim::scene::SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant = "");

}  // namespace sim::yaml

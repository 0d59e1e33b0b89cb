// The model of a 3D scene file (`dimensions: 3`) read from its YAML tree into sim::scene3d's
// definitions, with every fault reported as FILE:LINE:COL: message, as the 2D reader (sim/yaml)
// does and with its helpers. The keys are documented in scenes/README.md ("3D scenes").
#pragma once

#include <string>

#include "sim/scene3d/scene_def.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/scene_yaml.h"

namespace sim::yaml3d {

// the 3D model of the scene in `source`, which must say `dimensions: 3`; any key not the model's
// nor in `others` is an error naming the nearest valid key (a 2D key says why 3D has none).
// Throws sim::yaml::SceneError.
sim::scene3d::SceneDef readModel(const sim::yaml::SceneSource& source, const sim::yaml::OtherKeys& others = {});

// the model of text that has nothing but the model; `file` names it in messages
sim::scene3d::SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant = "");

}  // namespace sim::yaml3d

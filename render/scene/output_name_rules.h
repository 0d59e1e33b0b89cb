// Scene and variant names become the start of output file names (out/<scene>/<scene>-<variant>.png),
// beside the names the outputs themselves add (-t<time>, -impact<N>, -panels…, -strobe<N>; a pack's
// index.html): a name that reads as one of those would take another output's file, and one of the
// two would be lost. Checked when the scene is read, at the name's line, before anything is drawn.
#pragma once

#include <string>

#include "sim/yaml/scene_source.h"
#include "sim/yaml/yaml_reader.h"

namespace render::scene {

// why `name`, a variant's, would take another output's file name ("" when it would not)
std::string variantNameClash(const std::string& name);

// the scene's name and each variant's key checked (sim::yaml::SceneError at its line)
void checkOutputNames(const sim::yaml::SceneSource& source, const std::string& sceneName, const sim::yaml::Reader& reader);

}  // namespace render::scene

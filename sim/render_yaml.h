// The scene's `render:` block, read into RenderDef (internal to the rigidreel_scene target).
#pragma once

#include "render_def.h"
#include "yaml_reader.h"

namespace sim::yaml {

// fails through `reader` with FILE:LINE:COL on bad input
void readRender(const YAML::Node& node, const Reader& reader, RenderDef& out);

// `panels:` of the render block (`node` may be null): times within [0, duration], or `impacts`;
// default the duration when the scene has two or more variants; asking for panels of a scene
// without variants fails, since there is nothing to put side by side
void readPanels(const YAML::Node& node, const Reader& reader, double duration, size_t variants, PanelsDef& out);

}  // namespace sim::yaml

// The scene's `render:` block, read into RenderDef (internal to the rigidreel_scene target).
#pragma once

#include "sim/scene/render_def.h"
#include "sim/scene/scene_def.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;

// fails through `reader` with FILE:LINE:COL on bad input
void readRender(const YAML::Node& node, const Reader& reader, RenderDef& out);
// its keys of video timing and text (render_timing_yaml.cpp), called by readRender
void readTiming(const YAML::Node& node, const Reader& reader, RenderDef& out);
// the lecture overlays of the same render: block; arrows name bodies of `scene`, read before
void readOverlays(const YAML::Node& node, const Reader& reader, const SceneDef& scene, OverlaysDef& out);

// `panels:` of the render block (`node` may be null): times within [0, duration], or `impacts`;
// default the duration when the scene has two or more variants; asking for panels of a scene
// without variants fails, since there is nothing to put side by side
void readPanels(const YAML::Node& node, const Reader& reader, double duration, size_t variants, PanelsDef& out);

}  // namespace sim::yaml

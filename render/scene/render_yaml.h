// How to draw a scene, read from its file's YAML tree: the `render:` block and each body's `color`
// and `label`, every fault at FILE:LINE:COL (sim::yaml::SceneError).
#pragma once

#include "render/scene/render_def.h"
#include "sim/scene/scene_def.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/yaml_reader.h"

namespace render::scene {

// the keys of a scene file this reader reads: `render` at the top level, these in each body
inline constexpr const char* kRenderKey = "render";
inline const sim::yaml::Keys kBodyKeys = {"color", "label"};
// the poll's texts at the top level (and in a variant), read here too (poll_yaml.cpp)
inline const sim::yaml::Keys kPollKeys = {"question", "answer", "title"};

// the look of the scene in `source`, whose model (read before) is `model`
RenderDef readRender(const sim::yaml::SceneSource& source, const sim::scene::SceneDef& model);

// the keys of the frame itself, which 2D and 3D scenes share: size, fps, background, line_width,
// font_size, colors
void readFrame(const YAML::Node& node, const sim::yaml::Reader& reader, RenderDef& out);
// a color written "#rrggbb" under `key`
std::string readColor(const YAML::Node& n, const sim::yaml::Reader& reader, const std::string& key);
// each body's `color` (checked) and `label` (its name by default), in the order of `bodies`
std::vector<BodyLook> readLooks(const YAML::Node& bodies, const sim::yaml::Reader& reader);

// the block's parts, each in its own file: video timing and text (render_timing_yaml.cpp), the
// lecture overlays, and `panels:` (`node` may be null): times within [0, duration], or `impacts`;
// default the duration when the scene has two or more variants; asking for panels of a scene
// without variants fails, since there is nothing to put side by side
void readTiming(const YAML::Node& node, const sim::yaml::Reader& reader, RenderDef& out);
void readOverlays(const YAML::Node& node, const sim::yaml::Reader& reader, const sim::scene::SceneDef& scene, OverlaysDef& out);
// the poll (poll_yaml.cpp): `question:` and `answer:` of the scene's `root`, `answer_card` and
// `reveal` (within [0, duration]) of its render: `block` (may be null); `file` is named when the
// title card cannot fit its text
void readPoll(const YAML::Node& root, const YAML::Node& block, const sim::yaml::Reader& reader, const std::string& file,
              double duration, PollDef& out);
void readPanels(const YAML::Node& node, const sim::yaml::Reader& reader, double duration, size_t variants, PanelsDef& out);

}  // namespace render::scene

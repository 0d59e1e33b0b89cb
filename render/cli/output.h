// What `render` and `snapshot` share: checking their command-line values (a bad one is a
// UsageError, exit 2) and where outputs go (out/<scene>/<scene>[-<variant>]…).
#pragma once

#include <string>

#include "sim/scene/scene_def.h"

namespace render::cli {

struct FrameSize {
  int width = 0, height = 0;
};

// "WxH": even sides from render::scene::kMinFrameSide to render::scene::kMaxFrameSide pixels; throws UsageError
FrameSize parseSize(const std::string& text, const std::string& option = "--size");
// frames per second above 0 and at most render::scene::kMaxFps; throws UsageError
void checkFps(double fps, const std::string& option = "--fps");

// <root>/<scene>, created when missing; throws UsageError when it cannot be created or written
std::string outputDirectory(const std::string& root, const std::string& scene);
// "<scene>" or "<scene>-<variant>": the start of every output name of a run
std::string outputBase(const sim::scene::SceneDef& def);
std::string outputBase(const std::string& scene, const std::string& variant);
// the poll slide's file name: "<scene>-panels<when>[-strobe<N>].png", `when` "-t1.5" or "-impact2"
std::string panelsFileName(const std::string& scene, const std::string& when, int strobe);
// "-strobe<N>" for a still with N ghosts, "" without
std::string strobeSuffix(int strobe);
// a time for a file name: shortest form, at most 6 significant digits ("0.5", "1.23457")
std::string timeForName(double t);

}  // namespace render::cli

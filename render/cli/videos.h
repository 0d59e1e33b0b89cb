// The videos of a scene, as `rigidreel render` writes them: per variant (or the one asked for)
// a video and a poster PNG under <output>/<scene>/, optionally every frame as PNG. Shared by
// `render` and `lecture`.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "render/cli/scene_options.h"

namespace render::cli {

struct VideoOptions : SceneOptions {
  std::string output = "out";
  bool allVariants = false;
  std::string size;
  std::optional<double> fps;
  std::optional<double> duration;
  std::string format = "mp4";
  bool frames = false;
  bool quiet = false;
};

// told the path of each output file (or frames directory) once it is complete
using Wrote = std::function<void(const std::string& path)>;

// kExitOk, or kExitFailure after saying on standard error that the simulation diverged; throws
// UsageError, sim::yaml::SceneError, std::runtime_error (ffmpeg) and Interrupted (between frames)
int renderVideos(const VideoOptions& options, const Wrote& wrote);

}  // namespace render::cli

// `rigidreel render`: a scene into a video (mp4, webm or gif) with a poster PNG, and optionally
// every frame as PNG, under out/<scene>/.
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/videos.h"
#include "render/jobs/interrupt.h"

namespace render::cli {
using namespace render::jobs;

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<VideoOptions>();
  CLI::App* cmd = app.add_subcommand("render", "render a scene into a video under out/<scene>/, with a poster PNG");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->addTo(*cmd);
  cmd->add_option("-o,--output", o->output, "the output directory (default: out)");
  cmd->add_flag("--all-variants", o->allVariants, "one video per variant (the base scene when it has none)")->excludes("--variant");
  cmd->add_option("--size", o->size, "frame size WIDTHxHEIGHT in pixels, even (default: the scene's, 1280x720)");
  cmd->add_option("--fps", o->fps, "frames per second (default: the scene's, 60)");
  cmd->add_option("--duration", o->duration, "length of the video in seconds (default: the scene's duration)");
  cmd->add_option("--format", o->format, "mp4 (H.264, default), webm (VP9) or gif");
  cmd->add_flag("--frames", o->frames, "also write every frame as PNG into <scene>-frames/");
  cmd->add_flag("--quiet", o->quiet, "no progress bar and no summary");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible([&] { return renderVideos(*o, [](const std::string&) {}); }); });
}

}  // namespace render::cli

// `rigidreel render`: a scene into a video (mp4, webm or gif) with a poster PNG, and optionally
// every frame as PNG, under out/<scene>/: the options checked, the plan made, the plan written.
#include <cmath>
#include <iostream>
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/overlay_option.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/interrupt.h"
#include "render/video/plan_writer.h"

namespace render::cli {
using namespace render::trace;
using namespace render::jobs;
using namespace render::video;

namespace {

struct RenderCommand : SceneOptions, Verbosity {
  std::string output = "out";
  bool allVariants = false;
  std::string size;
  std::string overlay;  // another simulator's trace, drawn over ours
  std::optional<double> fps;
  std::optional<double> duration;
  std::string format = "mp4";
  bool frames = false;
  std::string trace;
};

// the plan's request, each value checked (UsageError)
VideoRequest request(const RenderCommand& o) {
  const std::optional<VideoFormat> format = videoFormatFromName(o.format);
  if (!format) throw UsageError("--format: unknown format '" + o.format + "'; choose mp4, webm or gif");
  VideoRequest r{.root = o.output,
                 .variant = o.variant,
                 .allVariants = o.allVariants,
                 .size = {},
                 .fps = o.fps,
                 .duration = o.duration,
                 .format = *format,
                 .frames = o.frames};
  if (!o.size.empty()) r.size = parseSize(o.size);
  if (o.fps) checkFps(*o.fps);
  if (o.duration && (!(*o.duration > 0.0) || !std::isfinite(*o.duration)))
    throw UsageError("--duration: the length of the video must be a positive number of seconds");
  return r;
}

int render(const RenderCommand& o) {
  // a trace written over what the run reads would destroy it before it is read whole
  refuseInputAsOutput(o.trace, o.scene, "--trace");
  refuseInputAsOutput(o.trace, o.overlay, "--trace", "the --overlay trace");
  const VideoRequest r = request(o);
  // -v: each file's path as it is written
  const auto wrote = [&o](const std::string& path) {
    if (o.verbose) std::cout << "wrote " << path << '\n';
  };
  if (!o.overlay.empty() && o.is3d()) throw UsageError("--overlay: a trace is drawn over 2D scenes only");
  if (o.is3d()) try {
      const RenderPlan3d plan = planVideos3d(o.variantLoader3d(), r);
      traced<TraceWriter3d>(o.trace, plan, [&](TraceWriter3d* trace) { writePlan3d(plan, o.quiet, wrote, trace); });
      return kExitOk;
    } catch (const VariantDiverged3d& d) {
      std::cerr << divergedMessage(o.scene, d.model, d) << '\n';
      return kExitFailure;
    }
  try {
    const RenderPlan plan = planVideos(withOverlay(o.variantLoader(), o.overlay), r);
    traced<TraceWriter>(o.trace, plan, [&](TraceWriter* trace) { writePlan(plan, o.quiet, wrote, trace); });
  } catch (const VariantDiverged& d) {
    std::cerr << videoDiverged(o.scene, d);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<RenderCommand>();
  CLI::App* cmd = app.add_subcommand("render", "render a scene into a video under out/<scene>/, with a poster PNG");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->SceneOptions::addTo(*cmd);
  cmd->add_option("-o,--output", o->output, "the output directory (default: out)");
  cmd->add_flag("--all-variants", o->allVariants, "one video per variant (the base scene when it has none)")
      ->excludes("--variant");
  cmd->add_option("--size", o->size, "frame size WIDTHxHEIGHT in pixels, even (default: the scene's, 1280x720)");
  cmd->add_option("--overlay", o->overlay, "another simulator's trace (CSV, as --trace writes): its bodies dashed over ours");
  cmd->add_option("--fps", o->fps, "frames per second (default: the scene's, 60)");
  cmd->add_option("--duration", o->duration, "length of the video in seconds (default: the scene's duration)");
  cmd->add_option("--format", o->format, "mp4 (H.264, default), webm (VP9) or gif");
  cmd->add_flag("--frames", o->frames, "also write every frame as PNG into <scene>-frames/");
  o->Verbosity::addTo(*cmd, "no progress bar and no summary", "also the path of each file as it is written");
  cmd->add_option("--trace", o->trace, "also write every step of the video's run to this CSV file (as simulate --trace)");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("render " + o->scene, [&] { return render(*o); }); });
}

}  // namespace render::cli

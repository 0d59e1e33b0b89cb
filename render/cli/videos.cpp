#include "render/cli/videos.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/space3d.h"
#include "render/draw/png_io.h"
#include "render/frame/scene_run.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/progress.h"
#include "render/video/recorder.h"
#include "render/video/time_map.h"
#include "render/video/video.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::draw;
using namespace render::frame;
using namespace render::video;
using namespace render::scene;

namespace {

namespace fs = std::filesystem;

class VideoSink : public FrameSink {
 public:
  explicit VideoSink(VideoWriter& video) : video_(video) {}
  void frame(long, const Image& image) override { video_.write(image); }

 private:
  VideoWriter& video_;
};

// one video of one variant (or of the base scene)
void renderOne(const VideoOptions& o, const render::scene::Scene& def, const Wrote& wrote) {
  const double fps = def.render.fps;
  const double duration = o.duration.value_or(def.model.duration);
  const VideoFormat format = *videoFormatFromName(o.format);
  const std::string dir = outputDirectory(o.output, def.model.name);
  const std::string base = outputBase(def.model);
  const std::string videoPath = dir + "/" + base + "." + videoExtension(format);

  const RunSurvey survey = surveyRun(def, duration);
  // frame k at the simulation time of video time k / fps, for every k / fps < the video's length:
  // the title card, then `duration` stretched by the slow-motion windows (exactly `duration` without)
  const TimeMap map = timeMapFor(def.render, survey.impactTimes, duration);
  const long count = map.frameCount(fps);
  const Camera camera = cameraFor(def, survey);
  GlContext gl(def.render.width, def.render.height);
  TextRenderer text;
  SceneRun run(def, camera, survey, &gl, &text);

  VideoWriter video(videoPath, format, def.render.width, def.render.height, fps);
  VideoSink videoSink(video);
  std::vector<FrameSink*> sinks = {&videoSink};
  std::unique_ptr<StagedDirectory> framesDir;
  std::unique_ptr<PngFrames> pngFrames;
  if (o.frames) {
    framesDir = std::make_unique<StagedDirectory>((fs::path(dir) / (base + "-frames")).string());
    pngFrames = std::make_unique<PngFrames>(framesDir->path(), count);
    sinks.push_back(pngFrames.get());
  }
  Progress progress(base, count, !o.quiet);
  record(run, map, fps, sinks, [&](long done) { progress.update(done); });
  progress.finish();
  video.finish();
  if (framesDir) framesDir->commit();
  const double seconds = progress.elapsed();

  // the poster: the last instant, with the scene's strobe ghosts when it asks for them
  const std::string posterPath = dir + "/" + base + ".png";
  SceneRun posterRun(def, camera, survey, &gl, &text);
  writePng(posterRun.frameAt(duration, def.render.strobe), posterPath);
  wrote(videoPath);
  wrote(posterPath);
  if (o.frames) wrote(dir + "/" + base + "-frames/");

  if (!o.quiet) {
    char rate[96];
    std::snprintf(rate, sizeof rate, "drawn in %.2f s (%.1f frames/s)", seconds, count / seconds);
    std::cout << videoPath << ": " << count << " frames, " << def.render.width << "x" << def.render.height << " at "
              << timeForName(fps) << " fps (" << timeForName(count / fps) << " s), " << rate << "\n";
    std::cout << posterPath << ": poster at t = " << timeForName(duration) << " s\n";
    if (o.frames) std::cout << dir << "/" << base << "-frames/: " << count << " PNG frames\n";
  }
}

}  // namespace

int renderVideos(const VideoOptions& o, const Wrote& wrote) {
  if (!videoFormatFromName(o.format)) throw UsageError("--format: unknown format '" + o.format + "'; choose mp4, webm or gif");
  std::optional<FrameSize> size;
  if (!o.size.empty()) size = parseSize(o.size);
  if (o.fps) checkFps(*o.fps);
  if (o.duration && (!(*o.duration > 0.0) || !std::isfinite(*o.duration)))
    throw UsageError("--duration: the length of the video must be a positive number of seconds");
  if (isSceneFile3d(o.scene)) return renderVideos3d(o, size, wrote);

  // the variants to render: every one (the base scene when there are none, as `check` does), the
  // one asked for, or the base scene
  std::vector<std::string> variants = {o.variant};
  if (o.allVariants) {
    const sim::scene::SceneDef base = o.load().model();
    if (!base.variantNames.empty()) variants = base.variantNames;
  }
  for (const std::string& v : variants) {
    VideoOptions one = o;
    one.variant = v;
    render::scene::Scene def = one.load().scene;
    if (size) def.render.width = size->width, def.render.height = size->height;
    if (o.fps) def.render.fps = *o.fps;
    try {
      renderOne(one, def, wrote);
    } catch (const sim::world::Diverged& d) {
      std::cerr << o.scene << ": the simulation diverged at t = " << timeForName(d.time) << ": body '"
                << def.model.bodies[d.body].name << "' has a non-finite state; try a smaller step (--dt "
                << timeForName(def.model.dt / 4) << ") or another integrator (--integrator rk4)\n";
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace render::cli

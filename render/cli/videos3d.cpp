// `rigidreel render` of a 3D scene: per variant (or the one asked for) a video drawn in perspective
// and a poster PNG under <output>/<scene>/, optionally every frame as PNG, named as 2D videos are.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/space3d.h"
#include "render/draw/png_io.h"
#include "render/frame3d/scene_run3.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/progress.h"
#include "render/video/recorder.h"
#include "render/video/time_map.h"
#include "render/video/video.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::video;
using namespace render::frame3d;

namespace {

class VideoSink3 : public FrameSink {
 public:
  explicit VideoSink3(VideoWriter& video) : video_(video) {}
  void frame(long, const Image& image) override { video_.write(image); }

 private:
  VideoWriter& video_;
};

// one video of one variant (or of the base scene), and its poster
void renderOne3(const VideoOptions& o, const render::scene3d::Scene& def, const Wrote& wrote) {
  const double fps = def.render.fps;
  const int width = def.render.width, height = def.render.height;
  const double duration = o.duration.value_or(def.model.duration);
  const VideoFormat format = *videoFormatFromName(o.format);
  const std::string dir = outputDirectory(o.output, def.model.name);
  const std::string base = outputBase(def.model.name, def.model.variant);
  const std::string videoPath = dir + "/" + base + "." + videoExtension(format);

  const RunSurvey3 survey = surveyRun(def, duration);
  // the title card, then `duration` stretched by the slow-motion windows (3D has no impacts to slow)
  const TimeMap map = timeMapFor(def.render, survey.impactTimes, duration);
  const long count = map.frameCount(fps);
  const Camera3 camera = cameraFor(def, survey);
  GlContext gl(width, height);
  TextRenderer text;
  SceneRun3 run(def, camera, survey, &gl, &text);

  VideoWriter video(videoPath, format, width, height, fps);
  VideoSink3 videoSink(video);
  std::vector<FrameSink*> sinks = {&videoSink};
  std::unique_ptr<StagedDirectory> framesDir;
  std::unique_ptr<PngFrames> pngFrames;
  if (o.frames) {
    framesDir = std::make_unique<StagedDirectory>(dir + "/" + base + "-frames");
    pngFrames = std::make_unique<PngFrames>(framesDir->path(), count);
    sinks.push_back(pngFrames.get());
  }
  Progress progress(base, count, !o.quiet);
  record(run, map, fps, sinks, [&](long done) { progress.update(done); });
  progress.finish();
  video.finish();
  if (framesDir) framesDir->commit();
  const double seconds = progress.elapsed();

  // the poster: the last instant
  const std::string posterPath = dir + "/" + base + ".png";
  SceneRun3 posterRun(def, camera, survey, &gl, &text);
  writePng(posterRun.frameAt(duration), posterPath);
  wrote(videoPath);
  wrote(posterPath);
  if (o.frames) wrote(dir + "/" + base + "-frames/");
  if (!o.quiet) {
    char rate[96];
    std::snprintf(rate, sizeof rate, "drawn in %.2f s (%.1f frames/s)", seconds, count / seconds);
    std::cout << videoPath << ": " << count << " frames, " << width << "x" << height << " at " << timeForName(fps) << " fps ("
              << timeForName(count / fps) << " s), in perspective, " << rate << "\n"
              << posterPath << ": poster at t = " << timeForName(duration) << " s\n";
    if (o.frames) std::cout << dir << "/" << base << "-frames/: " << count << " PNG frames\n";
  }
}

}  // namespace

int renderVideos3d(const VideoOptions& o, const std::optional<FrameSize>& size, const Wrote& wrote) {
  // every variant (the base scene when there are none), the one asked for, or the base scene
  std::vector<std::string> variants = {o.variant};
  if (o.allVariants) {
    const sim::scene3d::SceneDef base = o.load3().model();
    if (!base.variantNames.empty()) variants = base.variantNames;
  }
  for (const std::string& v : variants) {
    VideoOptions one = o;
    one.variant = v;
    render::scene3d::Scene def = one.load3().scene;
    if (size) def.render.width = size->width, def.render.height = size->height;
    if (o.fps) def.render.fps = *o.fps;
    try {
      renderOne3(one, def, wrote);
    } catch (const sim::world3d::Diverged& d) {
      std::cerr << divergedMessage(o.scene, def.model, d) << '\n';
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace render::cli

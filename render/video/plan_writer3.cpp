#include "render/video/plan_writer3.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/draw/png_io.h"
#include "render/frame/panels.h"
#include "render/frame3d/scene_run3.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/progress.h"
#include "render/video/output_names.h"
#include "render/video/recorder.h"

namespace render::video {
using namespace render::jobs;
using namespace render::frame3d;

namespace {

namespace fs = std::filesystem;

template <class Draw>
void drawing(const PlannedVariant3& v, VariantDiverged::While what, Draw&& draw) {
  try {
    draw();
  } catch (const sim::world3d::Diverged& d) {
    throw VariantDiverged3(d, v.scene.model, what);
  }
}

class VideoSink3 : public FrameSink {
 public:
  explicit VideoSink3(VideoWriter& video) : video_(video) {}
  void frame(long, const Image& image) override { video_.write(image); }

 private:
  VideoWriter& video_;
};

// one video, its frames as PNG when asked for, then its poster
void writeVideo(const PlannedVariant3& v, const VideoOutput3& out, bool quiet, const Wrote& wrote) {
  GlContext gl(out.width, out.height);
  TextRenderer text;
  SceneRun3 run(v.scene, out.camera, v.survey, &gl, &text);

  VideoWriter video(out.path, out.format, out.width, out.height, out.fps);
  VideoSink3 videoSink(video);
  std::vector<FrameSink*> sinks = {&videoSink};
  std::unique_ptr<StagedDirectory> framesDir;
  std::unique_ptr<PngFrames> pngFrames;
  if (!out.framesPath.empty()) {
    framesDir = std::make_unique<StagedDirectory>(fs::path(out.framesPath).parent_path().string());
    pngFrames = std::make_unique<PngFrames>(framesDir->path(), out.frameCount);
    sinks.push_back(pngFrames.get());
  }
  Progress progress(outputBase(v.scene.model.name, v.scene.model.variant), out.frameCount, !quiet);
  record(run, out.timeMap, out.fps, sinks, [&](long done) { progress.update(done); });
  progress.finish();
  video.finish();
  if (framesDir) framesDir->commit();
  const double seconds = progress.elapsed();

  SceneRun3 posterRun(v.scene, out.camera, v.survey, &gl, &text);
  writePng(posterRun.frameAt(out.duration), out.posterPath);
  wrote(out.path);
  wrote(out.posterPath);
  if (framesDir) wrote(out.framesPath);
  if (!quiet) {
    char rate[96];
    std::snprintf(rate, sizeof rate, "drawn in %.2f s (%.1f frames/s)", seconds, out.frameCount / seconds);
    std::cout << out.path << ": " << out.frameCount << " frames, " << out.width << "x" << out.height << " at "
              << timeForName(out.fps) << " fps (" << timeForName(out.frameCount / out.fps) << " s), in perspective, " << rate << "\n";
    std::cout << out.posterPath << ": poster at t = " << timeForName(out.duration) << " s\n";
    if (framesDir) std::cout << out.framesPath << ": " << out.frameCount << " PNG frames\n";
  }
}

// each shot: a fresh run per variant (trails and paths start from t = 0), alone or side by side
void writeStills(const RenderPlan3& plan, const Stills3& stills, const Wrote& wrote) {
  const render::scene3d::Scene& first = plan.variants.front().scene;
  GlContext gl(stills.width, stills.height);
  TextRenderer text;
  for (const StillOutput& shot : stills.shots) {
    std::vector<Image> frames;
    for (size_t i = 0; i < plan.variants.size(); ++i) {
      const PlannedVariant3& v = plan.variants[i];
      SceneRun3 run(v.scene, stills.camera, stills.surveys[i], &gl, &text);
      drawing(v, VariantDiverged::While::Stills, [&] { frames.push_back(run.frameAt(shot.instants[i])); });
    }
    if (stills.panels)
      writePng(render::frame::composePanels(frames, shot.titles, render::scene3d::makeStyle(first, first.render.height), text), shot.path);
    else
      writePng(frames.front(), shot.path);
    wrote(shot.path);
  }
}

}  // namespace

void writePlan3(const RenderPlan3& plan, bool quiet, const Wrote& wrote) {
  for (const VideoOutput3& video : plan.videos) {
    const PlannedVariant3& v = plan.variants[video.variant];
    createOutputDirectory(video.directory);
    drawing(v, VariantDiverged::While::Video, [&] { writeVideo(v, video, quiet, wrote); });
  }
  if (plan.stills) {
    createOutputDirectory(plan.stills->directory);
    writeStills(plan, *plan.stills, wrote);
  }
}

}  // namespace render::video

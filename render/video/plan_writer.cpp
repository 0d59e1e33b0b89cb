#include "render/video/plan_writer.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/draw/png_io.h"
#include "render/frame/panels.h"
#include "render/frame/scene_run.h"
#include "render/frame3d/scene_run3d.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/progress.h"
#include "render/scene/scene_style.h"
#include "render/scene3d/scene.h"
#include "render/video/output_names.h"
#include "render/video/recorder.h"
#include "render/video/still_draw_lists.h"

namespace render::video {
using render::frame::PixelDrawList;
using render::frame::SceneRun;
using namespace render::trace;
using namespace render::jobs;
using namespace render::draw;
using namespace render::frame;
using namespace render::scene;

namespace {

namespace fs = std::filesystem;

// the stills drawn by one run of each variant: their frames wait in memory for the panels to be put
// together (16 frames of 1280×720 are 59 MB a variant)
constexpr size_t kShotsPerRun = 16;

// what drawing a variant takes in each dimension: its run, its poster, how its frames are drawn
template <class D>
struct Drawing;
template <>
struct Drawing<Planar> {
  using Run = SceneRun;
  using Trace = TraceWriter;
  static constexpr const char* kView = "";
  // the poster's instant, with the scene's strobe ghosts when it asks for them, taken along the run
  static void poster(SceneRun& run, const VideoOutput& out, std::function<void(Image)> shot) {
    run.pictureAlong(out.posterTime, out.posterStrobe, std::move(shot));
  }
};
template <>
struct Drawing<Spatial> {
  using Run = render::frame3d::SceneRun3d;
  using Trace = TraceWriter3d;
  static constexpr const char* kView = "in perspective, ";
  static void poster(render::frame3d::SceneRun3d& run, const VideoOutput3d& out, std::function<void(Image)> shot) {
    run.pictureAlong(out.posterTime, std::move(shot));
  }
};

// `draw()`, a divergence of the simulation naming the variant and what was being drawn
template <class D, class Draw>
void drawing(const PlannedVariantOf<D>& v, DrawStage what, Draw&& draw) {
  try {
    draw();
  } catch (const sim::core::Diverged& d) {
    throw VariantDivergedOf<D>(d, v.scene.model, what);
  }
}

class VideoSink : public FrameSink {
 public:
  explicit VideoSink(VideoWriter& video) : video_(video) {}
  void frame(long, const Image& image) override { video_.write(image); }

 private:
  VideoWriter& video_;
};

// `trace` (when given) follows `run` from its start
template <class Run, class Trace>
void follow(Run& run, Trace* trace) {
  if (!trace) return;
  trace->rows(run.runWorld());
  run.follow(trace);
}

// one video, its frames as PNG when asked for, then its poster; `trace` follows the video's run
template <class D>
void writeVideo(const PlannedVariantOf<D>& v, const VideoOutputOf<D>& out, bool quiet, const Wrote& wrote,
                typename Drawing<D>::Trace* trace) {
  using Run = typename Drawing<D>::Run;
  // ffmpeg first: it starts (loads its libraries, sets up the encoder) while GL is loaded and the
  // poster drawn, not after (a 0.5 s clip of a 210-box pile: 0.65 -> 0.59 s wall)
  VideoWriter video(out.path, out.format, out.width, out.height, out.fps);
  GlContext gl(out.width, out.height);
  TextRenderer text;
  Run run(v.scene, out.camera, v.survey, &gl, &text);
  run.endAt(out.duration);
  follow(run, trace);
  // the poster from the video's own run (at its end, or at the start for a question), so that the
  // scene is stepped once for both
  Image poster;
  Drawing<D>::poster(run, out, [&poster](Image picture) { poster = std::move(picture); });

  VideoSink videoSink(video);
  std::vector<FrameSink*> sinks = {&videoSink};
  std::unique_ptr<StagedDirectory> framesDir;
  std::unique_ptr<PngFrames> pngFrames;
  if (!out.framesPath.empty()) {
    // (the path ends in '/', a directory's name)
    framesDir = std::make_unique<StagedDirectory>(fs::path(out.framesPath).parent_path().string());
    pngFrames = std::make_unique<PngFrames>(framesDir->path(), out.frameCount);
    sinks.push_back(pngFrames.get());
  }
  Progress progress(outputBase(v.scene.model.name, v.scene.model.variant), out.frameCount, !quiet);
  record(run, out.timeMap, out.fps, sinks, [&](long done) { progress.update(done); });
  // the poster, if the frames did not pass it; a trace follows the run to its end
  run.takePicturesAlong();
  if (trace) run.finish();
  progress.finish();
  video.finish();
  if (framesDir) framesDir->commit();
  const double seconds = progress.elapsed();

  writePng(poster, out.posterPath);
  wrote(out.path);
  wrote(out.posterPath);
  if (framesDir) wrote(out.framesPath);

  if (!quiet) {
    char rate[96];
    std::snprintf(rate, sizeof rate, "drawn in %.2f s (%.1f frames/s)", seconds, out.frameCount / seconds);
    std::cout << out.path << ": " << out.frameCount << " frames, " << out.width << "x" << out.height << " at "
              << timeForName(out.fps) << " fps (" << timeForName(out.frameCount / out.fps) << " s), " << Drawing<D>::kView << rate
              << "\n";
    std::cout << out.posterPath << ": poster at t = " << timeForName(out.posterTime) << " s\n";
    if (framesDir) std::cout << out.framesPath << ": " << out.frameCount << " PNG frames\n";
  }
}

// the stills, a batch of shots at a time: each variant runs once per batch, through its instants
// (SceneRun::framesAt), then each shot is written, alone or with the other variants beside it
// (`trace` follows the first run, taken on to its end)
void writeStills(const RenderPlan& plan, const Stills& stills, const Wrote& wrote, TraceWriter* trace) {
  const render::scene::Scene& first = stills.scenes.front();
  GlContext gl(stills.width, stills.height);
  TextRenderer text;
  const bool drawLists = !stills.shots.empty() && !stills.shots.front().drawListPath.empty();
  for (size_t from = 0; from < stills.shots.size(); from += kShotsPerRun) {
    const size_t count = std::min(kShotsPerRun, stills.shots.size() - from);
    std::vector<std::vector<Image>> frames(count, std::vector<Image>(plan.variants.size()));  // [shot][variant]
    std::vector<std::vector<PixelDrawList>> lists(count, std::vector<PixelDrawList>(plan.variants.size()));
    for (size_t i = 0; i < plan.variants.size(); ++i) {
      const PlannedVariant& v = plan.variants[i];
      std::vector<double> instants;
      for (size_t k = 0; k < count; ++k) instants.push_back(stills.shots[from + k].instants[i]);
      SceneRun run(stills.scenes[i], stills.camera, stills.surveys[i], &gl, &text);
      TraceWriter* const traced = from == 0 && i == 0 ? trace : nullptr;
      follow(run, traced);
      drawing<Planar>(v, DrawStage::Stills, [&] {
        if (drawLists)
          run.framesAndListsAt(instants, stills.strobe, [&](size_t k, Image frame, DrawList list) {
            frames[k][i] = std::move(frame);
            lists[k][i] = frameDrawList(stills, i, list, text);
          });
        else run.framesAt(instants, stills.strobe, [&](size_t k, Image frame) { frames[k][i] = std::move(frame); });
        if (traced) run.finish();
      });
    }
    for (size_t k = 0; k < count; ++k) {
      const StillOutput& shot = stills.shots[from + k];
      if (stills.panels)
        writePng(composePanels(frames[k], stills.grid, shot.titles, stills.caption, makeStyle(first, first.render.height), text),
                 shot.path);
      else writePng(frames[k].front(), shot.path);
      wrote(shot.path);
      if (!drawLists) continue;
      AtomicFile json(shot.drawListPath);
      writePixelDrawList(json.stream(), stillDrawList(stills, shot, lists[k], text));
      json.commit();
      wrote(shot.drawListPath);
    }
  }
}

// 3D stills, shot by shot: a fresh run per variant (its trails and paths start from t = 0), alone or
// side by side
// (`trace` follows the first run, taken on to its end)
void writeStills(const RenderPlan3d& plan, const Stills3d& stills, const Wrote& wrote, TraceWriter3d* trace) {
  const render::scene3d::Scene& first = stills.scenes.front();
  GlContext gl(stills.width, stills.height);
  TextRenderer text;
  for (const StillOutput& shot : stills.shots) {
    std::vector<Image> frames;
    for (size_t i = 0; i < plan.variants.size(); ++i) {
      const PlannedVariant3d& v = plan.variants[i];
      render::frame3d::SceneRun3d run(stills.scenes[i], stills.camera, stills.surveys[i], &gl, &text);
      TraceWriter3d* const traced = &shot == &stills.shots.front() && i == 0 ? trace : nullptr;
      follow(run, traced);
      drawing<Spatial>(v, DrawStage::Stills, [&] {
        frames.push_back(run.frameAt(shot.instants[i]));
        if (traced) run.finish();
      });
    }
    if (stills.panels)
      writePng(composePanels(frames, stills.grid, shot.titles, stills.caption,
                             render::scene3d::makeStyle(first, first.render.height), text),
               shot.path);
    else writePng(frames.front(), shot.path);
    wrote(shot.path);
  }
}

// every video with its poster, then the stills
template <class D>
void writeAll(const RenderPlanOf<D>& plan, bool quiet, const Wrote& wrote, typename Drawing<D>::Trace* trace) {
  if (trace && plan.variants.size() != 1) throw UsageError("--trace: a trace is one variant's run; choose one with --variant");
  for (const VideoOutputOf<D>& video : plan.videos) {
    const PlannedVariantOf<D>& v = plan.variants[video.variant];
    createOutputDirectory(video.directory);
    drawing<D>(v, DrawStage::Video, [&] { writeVideo<D>(v, video, quiet, wrote, trace); });
    trace = nullptr;
  }
  if (plan.stills) {
    createOutputDirectory(plan.stills->directory);
    writeStills(plan, *plan.stills, wrote, trace);
  }
}

}  // namespace

void createOutputDirectory(const std::string& dir, const std::string& option) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir))
    throw UsageError(option + ": cannot create the output directory " + dir + " (" +
                     (error ? error.message() : "a file is in the way") + "); choose another with " + option + " DIR");
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError(option + ": cannot write in " + dir + "; choose another directory with " + option + " DIR");
}

void writePlan(const RenderPlan& plan, bool quiet, const Wrote& wrote, TraceWriter* trace) {
  writeAll(plan, quiet, wrote, trace);
}

void writePlan3d(const RenderPlan3d& plan, bool quiet, const Wrote& wrote, TraceWriter3d* trace) {
  writeAll(plan, quiet, wrote, trace);
}

}  // namespace render::video

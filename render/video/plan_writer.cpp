#include "render/video/plan_writer.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/draw/png_io.h"
#include "render/frame/panels.h"
#include "render/frame/scene_run.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/progress.h"
#include "render/jobs/stale_parts.h"
#include "render/scene/scene_style.h"
#include "render/video/output_names.h"
#include "render/video/recorder.h"

namespace render::video {
using namespace render::jobs;

namespace {

namespace fs = std::filesystem;

// the stills drawn by one run of each variant: their frames wait in memory for the panels to be put
// together (16 frames of 1280×720 are 59 MB a variant)
constexpr size_t kShotsPerRun = 16;

// `dir`, created when missing; throws UsageError when it cannot be created or written
void createDirectory(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir))
    throw UsageError("-o: cannot create the output directory " + dir + " (" +
                     (error ? error.message() : "a file is in the way") + "); choose another with -o DIR");
  if (::access(dir.c_str(), W_OK) != 0) throw UsageError("-o: cannot write in " + dir + "; choose another directory with -o DIR");
}

// `draw()`, a divergence of the simulation naming the variant and what was being drawn
template <class Draw>
void drawing(const PlannedVariant& v, VariantDiverged::While what, Draw&& draw) {
  try {
    draw();
  } catch (const sim::world::Diverged& d) {
    throw VariantDiverged(d, v.scene.model, what);
  }
}

class VideoSink : public FrameSink {
 public:
  explicit VideoSink(VideoWriter& video) : video_(video) {}
  void frame(long, const Image& image) override { video_.write(image); }

 private:
  VideoWriter& video_;
};

// a directory filled under a temporary name and renamed over the old one when complete
class StagedDirectory {
 public:
  explicit StagedDirectory(const fs::path& final) : final_(final), staging_(final.parent_path() / stagingName(final)) {
    removeStaleParts(final_.string());
    fs::remove_all(staging_);
    fs::create_directories(staging_);
  }
  ~StagedDirectory() {
    std::error_code ignored;
    if (!committed_) fs::remove_all(staging_, ignored);
  }
  std::string path() const { return staging_.string(); }
  void commit() {
    fs::remove_all(final_);
    fs::rename(staging_, final_);
    committed_ = true;
  }

 private:
  // ".<name>.part-<pid>" (appended piece by piece: g++ 12 warns of overlapping copies in "." + name)
  static std::string stagingName(const fs::path& final) {
    std::string name = ".";
    name += final.filename().string();
    name += ".part-" + std::to_string(::getpid());
    return name;
  }

  fs::path final_, staging_;
  bool committed_ = false;
};

// one video, its frames as PNG when asked for, then its poster
void writeVideo(const PlannedVariant& v, const VideoOutput& out, bool quiet, const Wrote& wrote) {
  GlContext gl(out.width, out.height);
  TextRenderer text;
  SceneRun run(v.scene, out.camera, v.survey, &gl, &text);

  VideoWriter video(out.path, out.format, out.width, out.height, out.fps);
  VideoSink videoSink(video);
  std::vector<FrameSink*> sinks = {&videoSink};
  std::unique_ptr<StagedDirectory> framesDir;
  std::unique_ptr<PngFrames> pngFrames;
  if (!out.framesPath.empty()) {
    // (the path ends in '/', a directory's name)
    framesDir = std::make_unique<StagedDirectory>(fs::path(out.framesPath).parent_path());
    pngFrames = std::make_unique<PngFrames>(framesDir->path(), out.frameCount);
    sinks.push_back(pngFrames.get());
  }
  Progress progress(outputBase(v.scene.model), out.frameCount, !quiet);
  record(run, out.timeMap, out.fps, sinks, [&](long done) { progress.update(done); });
  progress.finish();
  video.finish();
  if (framesDir) framesDir->commit();
  const double seconds = progress.elapsed();

  // the poster: the last instant, with the scene's strobe ghosts when it asks for them
  SceneRun posterRun(v.scene, out.camera, v.survey, &gl, &text);
  writePng(posterRun.frameAt(out.duration, out.posterStrobe), out.posterPath);
  wrote(out.path);
  wrote(out.posterPath);
  if (framesDir) wrote(out.framesPath);

  if (!quiet) {
    char rate[96];
    std::snprintf(rate, sizeof rate, "drawn in %.2f s (%.1f frames/s)", seconds, out.frameCount / seconds);
    std::cout << out.path << ": " << out.frameCount << " frames, " << out.width << "x" << out.height << " at "
              << timeForName(out.fps) << " fps (" << timeForName(out.frameCount / out.fps) << " s), " << rate << "\n";
    std::cout << out.posterPath << ": poster at t = " << timeForName(out.duration) << " s\n";
    if (framesDir) std::cout << out.framesPath << ": " << out.frameCount << " PNG frames\n";
  }
}

// the stills, a batch of shots at a time: each variant runs once per batch, through its instants
// (SceneRun::framesAt), then each shot is written, alone or with the other variants beside it
void writeStills(const RenderPlan& plan, const Stills& stills, const Wrote& wrote) {
  const render::scene::Scene& first = plan.variants.front().scene;
  GlContext gl(stills.width, stills.height);
  TextRenderer text;
  for (size_t from = 0; from < stills.shots.size(); from += kShotsPerRun) {
    const size_t count = std::min(kShotsPerRun, stills.shots.size() - from);
    std::vector<std::vector<Image>> frames(count, std::vector<Image>(plan.variants.size()));  // [shot][variant]
    for (size_t i = 0; i < plan.variants.size(); ++i) {
      const PlannedVariant& v = plan.variants[i];
      std::vector<double> instants;
      for (size_t k = 0; k < count; ++k) instants.push_back(stills.shots[from + k].instants[i]);
      SceneRun run(v.scene, stills.camera, stills.surveys[i], &gl, &text);
      drawing(v, VariantDiverged::While::Stills, [&] {
        run.framesAt(instants, stills.strobe, [&](size_t k, Image frame) { frames[k][i] = std::move(frame); });
      });
    }
    for (size_t k = 0; k < count; ++k) {
      const StillOutput& shot = stills.shots[from + k];
      if (stills.panels)
        writePng(composePanels(frames[k], shot.titles, makeStyle(first, first.render.height), text), shot.path);
      else
        writePng(frames[k].front(), shot.path);
      wrote(shot.path);
    }
  }
}

}  // namespace

void writePlan(const RenderPlan& plan, bool quiet, const Wrote& wrote) {
  for (const VideoOutput& video : plan.videos) {
    const PlannedVariant& v = plan.variants[video.variant];
    createDirectory(video.directory);
    drawing(v, VariantDiverged::While::Video, [&] { writeVideo(v, video, quiet, wrote); });
  }
  if (plan.stills) {
    createDirectory(plan.stills->directory);
    writeStills(plan, *plan.stills, wrote);
  }
}

}  // namespace render::video

// The render plan: everything `render`, `snapshot` and `lecture` write, decided in one pure step
// before anything is drawn (no GL, no file written): the variants, each surveyed once; per output
// its path, its variant, its instants or time map, its camera, size and fps. The command line
// builds a plan and hands it to the writer (plan_writer.h); `lecture --list` prints its paths(), so
// that what the pack lists is what its jobs write, by construction.
//
//   scene file ─load each variant─▶ surveyRun (once per variant) ─▶ RenderPlan ─writePlan─▶ files
//                                                                      └─paths()─▶ lecture --list
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/survey.h"
#include "render/scene/scene.h"
#include "render/video/time_map.h"
#include "render/video/video.h"
#include "sim/world/world.h"

namespace render::video {
using namespace render::draw;
using namespace render::frame;

struct FrameSize {
  int width = 0, height = 0;
};

// the scene file's variant ("" for the base scene) with the command line's overrides (--integrator,
// --dt, ...); throws sim::yaml::SceneError or UsageError
using LoadVariant = std::function<render::scene::Scene(const std::string& variant)>;

// one variant as it is drawn: the scene with the command line's size (and fps), and its survey, the
// one run of its world that every camera, scale, time map and impact instant of it comes from
struct PlannedVariant {
  render::scene::Scene scene;
  RunSurvey survey;
};

// a video of one variant, with its poster (the last instant) and, with --frames, every frame as PNG
struct VideoOutput {
  size_t variant = 0;      // in RenderPlan::variants
  std::string directory;   // <root>/<scene>, the variant's scene name (a variant may rename it)
  std::string path;        // <directory>/<base>.mp4 (.webm, .gif)
  std::string posterPath;  // <directory>/<base>.png
  std::string framesPath;  // <directory>/<base>-frames/, or empty
  VideoFormat format = VideoFormat::Mp4;
  int width = 0, height = 0;
  double fps = 0.0;
  double duration = 0.0;   // s of simulation: the poster's instant
  int posterStrobe = 0;    // the poster's ghosts
  TimeMap timeMap;         // video time to simulation time: the title card, slow motion
  long frameCount = 0;
  Camera camera;           // fitted over the variant's survey; the poster's too
};

// one still image: a variant at an instant, or the variants side by side at theirs (a poll panel)
struct StillOutput {
  std::string path;
  std::vector<double> instants;     // s, one per variant of the stills
  std::vector<std::string> titles;  // the panels' titles, "A: center", … (empty for one variant)
};

// still images of every variant of the plan (left to right), drawn alike: one camera, one strobe and
// (side by side) one scale for arrows and bars
struct Stills {
  std::string directory;           // <root>/<scene>
  std::vector<RunSurvey> surveys;  // the variants', side by side with scales shared (shareScales)
  bool panels = false;             // the variants side by side in each image
  int strobe = 0;
  int width = 0, height = 0;       // of one variant's frame
  Camera camera;                   // over every variant's run, beside the widest energy panel
  std::vector<StillOutput> shots;
};

struct RenderPlan {
  std::string scene;  // its name (the base scene's)
  std::vector<PlannedVariant> variants;
  std::vector<VideoOutput> videos;
  std::optional<Stills> stills;

  // every path written, in the order written: each video, its poster (and frames), then each still
  std::vector<std::string> paths() const;
};

// a variant's simulation diverged: planning (its survey), drawing its video or poster, or a still
struct VariantDiverged : sim::world::Diverged {
  enum class While { Planning, Video, Stills };
  VariantDiverged(const sim::world::Diverged& d, const sim::scene::SceneDef& variant, While stage)
      : Diverged(d), model(variant), when(stage) {}
  sim::scene::SceneDef model;  // the variant's: its bodies' names, its step
  While when;
};

// what `render` asks for, its values checked
struct VideoRequest {
  std::string root = "out";
  std::string variant = "";  // "" the base scene
  bool allVariants = false;  // every variant (the base scene when there are none)
  std::optional<FrameSize> size = {};
  std::optional<double> fps = {};
  std::optional<double> duration = {};  // s, instead of the scene's
  VideoFormat format = VideoFormat::Mp4;
  bool frames = false;
};

// what `snapshot` asks for, its values checked: times or impacts, one variant or panels of all
struct StillRequest {
  std::string root = "out";
  std::string file = "";  // the scene file, named in messages
  std::string variant = "";
  std::vector<double> times = {};  // s; empty with `impacts`
  bool impacts = false;
  bool panels = false;
  std::optional<int> strobe = {};  // ghosts, instead of the scene's
  std::optional<FrameSize> size = {};
};

// what `lecture` asks for a scene: every variant's video and poster, then its `panels:`
struct LectureRequest {
  std::string root = "out/lecture";
  std::string file = "";  // the scene file, named in messages
  std::optional<FrameSize> size = {};
  std::optional<double> fps = {};
};

// `render`: each variant asked for, surveyed over the video's duration, its video and poster.
// Throws as `load`, VariantDiverged
RenderPlan planVideos(const LoadVariant& load, const VideoRequest& request);
// `snapshot`: the variant asked for, or every one side by side, surveyed, at the times asked for or
// at their impacts. Throws as `load`, UsageError (a time outside a variant's duration, --impacts of
// a variant without impacts, --panels of a scene without variants), VariantDiverged
RenderPlan planStills(const LoadVariant& load, const StillRequest& request);
// `lecture` (a job, and --list): every variant's video and poster, then the poll panels of the
// scene's `panels:` key; each variant surveyed once for both. Throws as `load`,
// sim::yaml::SceneError (`panels: impacts` where a variant has none), VariantDiverged
RenderPlan planLecture(const LoadVariant& load, const LectureRequest& request);

}  // namespace render::video

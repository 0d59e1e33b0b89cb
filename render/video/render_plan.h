// The render plan: everything `render`, `snapshot` and `lecture` write, decided in one pure step
// before anything is drawn (no GL, no file written): the variants, each surveyed once; per output
// its path, its variant, its instants or time map, its camera, size and fps. The command line
// builds a plan and hands it to the writer (plan_writer.h); `lecture --list` prints its paths(), so
// that what the pack lists is what its jobs write, by construction.
//
//   scene file ─load each variant─▶ surveyRun (once per variant) ─▶ RenderPlan ─writePlan─▶ files
//                                                                      └─paths()─▶ lecture --list
//
// 2D and 3D scenes are planned by the same code: the types are written once over the scene's
// dimension (Planar, Spatial); a 3D plan makes the same outputs in perspective (its stills at its
// impacts too, `--impacts`), without strobes or pixel draw lists, which are 2D frames' only.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/panels.h"
#include "render/frame/survey.h"
#include "render/frame3d/survey3d.h"
#include "render/scene/scene.h"
#include "render/scene3d/scene.h"
#include "render/video/time_map.h"
#include "render/video/video.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::video {

struct FrameSize {
  int width = 0, height = 0;
};

// what a plan takes of a scene's dimension: the scene, the survey of its run, the camera that draws
// it
struct Planar {
  using Scene = render::scene::Scene;
  using Survey = render::frame::RunSurvey;
  using Camera = render::draw::Camera;
};
struct Spatial {
  using Scene = render::scene3d::Scene;
  using Survey = render::frame3d::RunSurvey3d;
  using Camera = render::draw3d::Camera3d;
};
template <class D>
using ModelOf = decltype(D::Scene::model);  // the variant's scene definition (sim::scene or sim::scene3d)

// the scene file's variant ("" for the base scene) with the command line's overrides (--integrator,
// --dt, ...); throws sim::yaml::SceneError or UsageError
template <class D>
using LoadVariantOf = std::function<typename D::Scene(const std::string& variant)>;

// one variant as it is drawn: the scene with the command line's size (and fps), and its survey, the
// one run of its world that every camera, scale, time map and impact instant of it comes from
template <class D>
struct PlannedVariantOf {
  typename D::Scene scene;
  typename D::Survey survey;
};

// a video of one variant, with its poster and, with --frames, every frame as PNG
template <class D>
struct VideoOutputOf {
  size_t variant = 0;      // in RenderPlan::variants
  std::string directory;   // <root>/<scene>, the variant's scene name (a variant may rename it)
  std::string path;        // <directory>/<base>.mp4 (.webm, .gif)
  std::string posterPath;  // <directory>/<base>.png
  std::string framesPath;  // <directory>/<base>-frames/, or empty
  VideoFormat format = VideoFormat::Mp4;
  int width = 0, height = 0;
  double fps = 0.0;
  double duration = 0.0;  // s of simulation
  // the poster's instant: the last, or 0 for a poll (a question's poster must not show its answer)
  double posterTime = 0.0;
  int posterStrobe = 0;  // the poster's ghosts (2D only)
  TimeMap timeMap;       // video time to simulation time: the title card, slow motion
  long frameCount = 0;
  typename D::Camera camera;  // fitted over the variant's survey; the poster's too
};

// one still image: a variant at an instant, or the variants side by side at theirs (a poll panel)
struct StillOutput {
  std::string path;
  std::vector<double> instants;     // s, one per variant of the stills
  std::vector<std::string> titles;  // the panels' titles, "A: center", "B: Off center", … (empty for one variant)
  std::string drawListPath;         // <path without .png>.json with --draw-list (pixel_draw_list.h), else empty
};

// still images of every variant of the plan, drawn alike: one camera, one strobe and (on a panel
// sheet) one scale for arrows and bars
template <class D>
struct StillsOf {
  std::string directory;                  // <root>/<scene>
  std::vector<typename D::Scene> scenes;  // each variant as its stills draw it (a panel: its frame's size, its text, no caption)
  std::vector<typename D::Survey> surveys;  // the variants', side by side with scales shared (shareScales)
  bool panels = false;                      // the variants on one sheet in each image (panels.h)
  render::frame::PanelGrid grid;            // that sheet's layout (panels only)
  std::string caption;                      // under the sheet's grid, once (panels only)
  int strobe = 0;                           // (2D only)
  int width = 0, height = 0;                // of one variant's frame
  typename D::Camera camera;                // over every variant's run and (2D panels) all each panel draws
  std::vector<StillOutput> shots;
};

template <class D>
struct RenderPlanOf {
  std::string scene;  // its name (the base scene's)
  std::vector<PlannedVariantOf<D>> variants;
  std::vector<VideoOutputOf<D>> videos;
  std::optional<StillsOf<D>> stills;

  // every path written, in the order written: each video, its poster (and frames), then each still
  // (and its draw list)
  std::vector<std::string> paths() const;
};

// a variant's simulation diverged: planning (its survey), drawing its video or poster, or a still
enum class DrawStage { Planning, Video, Stills };
template <class D>
struct VariantDivergedOf : sim::core::Diverged {
  using While = DrawStage;
  VariantDivergedOf(const sim::core::Diverged& d, const ModelOf<D>& variant, While stage)
      : sim::core::Diverged(d), model(variant), when(stage) {}
  ModelOf<D> model;  // the variant's: its bodies' names, its step
  While when;
};

using LoadVariant = LoadVariantOf<Planar>;
using PlannedVariant = PlannedVariantOf<Planar>;
using VideoOutput = VideoOutputOf<Planar>;
using Stills = StillsOf<Planar>;
using RenderPlan = RenderPlanOf<Planar>;
using VariantDiverged = VariantDivergedOf<Planar>;
using LoadVariant3d = LoadVariantOf<Spatial>;
using PlannedVariant3d = PlannedVariantOf<Spatial>;
using VideoOutput3d = VideoOutputOf<Spatial>;
using Stills3d = StillsOf<Spatial>;
using RenderPlan3d = RenderPlanOf<Spatial>;
using VariantDiverged3d = VariantDivergedOf<Spatial>;

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
  std::optional<int> strobe = {};      // ghosts, instead of the scene's
  std::optional<FrameSize> size = {};  // of the frame; with `panels`, of the whole sheet (default 1920 × 1080)
  bool drawList = false;               // each PNG's draw list in its pixels beside it (2D only)
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

// the same for a 3D scene; `--strobe` and `--draw-list` are UsageErrors (earlier poses are ghosted,
// and draw lists written, for 2D frames only). Throw as `load`, VariantDiverged3d
RenderPlan3d planVideos3d(const LoadVariant3d& load, const VideoRequest& request);
RenderPlan3d planStills3d(const LoadVariant3d& load, const StillRequest& request);
RenderPlan3d planLecture3d(const LoadVariant3d& load, const LectureRequest& request);

}  // namespace render::video

// The render plan of a 3D scene (dimensions: 3), as render_plan.h makes it for 2D: everything
// `render`, `snapshot` and `lecture` write, decided before anything is drawn; each variant surveyed
// once (render/frame3d/survey3.h), every output named as 2D outputs are (output_names.h), with its
// perspective camera. 3D has no contacts: no impacts to slow down or to take stills at, no strobe.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/frame3d/survey3.h"
#include "render/scene3d/scene.h"
#include "render/video/render_plan.h"
#include "sim/world3d/world.h"

namespace render::video {

// the 3D scene file's variant ("" for the base scene) with the command line's overrides
using LoadVariant3 = std::function<render::scene3d::Scene(const std::string& variant)>;

struct PlannedVariant3 {
  render::scene3d::Scene scene;
  render::frame3d::RunSurvey3 survey;
};

// a video of one variant and its poster (the last instant), as VideoOutput, in perspective
struct VideoOutput3 {
  size_t variant = 0;
  std::string directory, path, posterPath, framesPath;
  VideoFormat format = VideoFormat::Mp4;
  int width = 0, height = 0;
  double fps = 0.0;
  double duration = 0.0;
  TimeMap timeMap;
  long frameCount = 0;
  render::draw3d::Camera3 camera;
};

// stills of every variant, drawn alike: one camera over all their runs, one scale side by side
struct Stills3 {
  std::string directory;
  std::vector<render::frame3d::RunSurvey3> surveys;
  bool panels = false;
  int width = 0, height = 0;
  render::draw3d::Camera3 camera;
  std::vector<StillOutput> shots;
};

struct RenderPlan3 {
  std::string scene;
  std::vector<PlannedVariant3> variants;
  std::vector<VideoOutput3> videos;
  std::optional<Stills3> stills;

  // every path written, in the order written (RenderPlan::paths)
  std::vector<std::string> paths() const;
};

// a 3D variant's simulation diverged
struct VariantDiverged3 : sim::world3d::Diverged {
  VariantDiverged3(const sim::world3d::Diverged& d, const sim::scene3d::SceneDef& variant, VariantDiverged::While stage)
      : Diverged(d), model(variant), when(stage) {}
  sim::scene3d::SceneDef model;
  VariantDiverged::While when;
};

// as planVideos, planStills and planLecture; `--impacts` and `--strobe` are UsageErrors (nothing
// collides in 3D, and earlier poses are ghosted in 2D frames only). Throw as `load`, VariantDiverged3
RenderPlan3 planVideos3(const LoadVariant3& load, const VideoRequest& request);
RenderPlan3 planStills3(const LoadVariant3& load, const StillRequest& request);
RenderPlan3 planLecture3(const LoadVariant3& load, const LectureRequest& request);

}  // namespace render::video

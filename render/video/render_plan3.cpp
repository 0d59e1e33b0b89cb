#include "render/video/render_plan3.h"

#include <filesystem>

#include "render/frame/panels.h"
#include "render/frame3d/energy3.h"
#include "render/jobs/exit_status.h"
#include "render/video/output_names.h"
#include "sim/core/step_limit.h"

namespace render::video {
using namespace render::jobs;
using namespace render::frame3d;

namespace {

std::vector<render::scene3d::Scene> variantsOf(render::scene3d::Scene base, const LoadVariant3& load) {
  if (base.model.variantNames.empty()) return {std::move(base)};
  std::vector<render::scene3d::Scene> scenes;
  for (const std::string& name : base.model.variantNames) scenes.push_back(load(name));
  return scenes;
}

std::string directoryOf(const std::string& root, const sim::scene3d::SceneDef& model) {
  return (std::filesystem::path(root) / model.name).string();
}

std::string baseOf(const sim::scene3d::SceneDef& model) { return outputBase(model.name, model.variant); }

// each variant at the size (and frame rate) asked for, surveyed from 0 to `until` (its duration when negative)
RenderPlan3 surveyed(std::vector<render::scene3d::Scene> scenes, const std::optional<FrameSize>& size,
                     const std::optional<double>& fps, double until) {
  RenderPlan3 plan;
  plan.scene = scenes.front().model.name;
  for (render::scene3d::Scene& scene : scenes) {
    if (size) scene.render.width = size->width, scene.render.height = size->height;
    if (fps) scene.render.fps = *fps;
    try {
      RunSurvey3 survey = surveyRun(scene, until);
      plan.variants.push_back({std::move(scene), std::move(survey)});
    } catch (const sim::world3d::Diverged& d) {
      throw VariantDiverged3(d, scene.model, VariantDiverged::While::Planning);
    }
  }
  return plan;
}

VideoOutput3 videoOf(const RenderPlan3& plan, size_t i, const std::string& root, double duration, VideoFormat format, bool frames) {
  const PlannedVariant3& v = plan.variants[i];
  const render::scene::RenderDef& r = v.scene.render;
  const std::string directory = directoryOf(root, v.scene.model);
  const std::string base = directory + "/" + baseOf(v.scene.model);
  // the title card, then `duration` stretched by the slow-motion windows (3D has no impacts to slow)
  TimeMap map = timeMapFor(r, v.survey.impactTimes, duration);
  const long count = map.frameCount(r.fps);
  return {.variant = i,
          .directory = directory,
          .path = base + "." + videoExtension(format),
          .posterPath = base + ".png",
          .framesPath = frames ? base + "-frames/" : "",
          .format = format,
          .width = r.width,
          .height = r.height,
          .fps = r.fps,
          .duration = duration,
          .timeMap = std::move(map),
          .frameCount = count,
          .camera = cameraFor(v.scene, v.survey)};
}

// every variant at each of `times` (inside every variant's duration), alone or side by side
Stills3 stillsOf(const RenderPlan3& plan, const std::vector<double>& times, bool panels, const std::string& root) {
  const render::scene3d::Scene& first = plan.variants.front().scene;
  std::vector<RunSurvey3> surveys;
  for (const PlannedVariant3& v : plan.variants) surveys.push_back(v.survey);
  if (panels) {
    std::vector<RunSurvey3*> all;
    for (RunSurvey3& survey : surveys) all.push_back(&survey);
    shareScales(all);
  }
  // one camera over every variant's run, beside the widest energy panel among them
  Box3 bounds;
  size_t widest = 0;
  double widestBand = -1.0;
  for (size_t i = 0; i < plan.variants.size(); ++i) {
    const render::scene3d::Scene& def = plan.variants[i].scene;
    bounds.add(surveys[i].bounds);
    const double band = EnergyPanel3::bandPx(def, surveys[i], def.render.height);
    if (band > widestBand) widest = i, widestBand = band;
  }
  Stills3 s{.directory = directoryOf(root, first.model),
            .surveys = surveys,
            .panels = panels,
            .width = first.render.width,
            .height = first.render.height,
            .camera = cameraFor(plan.variants[widest].scene, surveys[widest], bounds),
            .shots = {}};
  for (double t : times) {
    for (const PlannedVariant3& v : plan.variants)
      if (t < 0.0 || t > v.scene.model.duration)
        throw UsageError("--at: " + timeForName(t) + " s is outside the scene's duration [0, " +
                         timeForName(v.scene.model.duration) + "]");
    StillOutput out{.path = s.directory + "/", .instants = std::vector<double>(plan.variants.size(), t), .titles = {}};
    if (panels) {
      out.path += panelsFileName(first.model.name, "-t" + timeForName(t), 0);
      for (size_t i = 0; i < plan.variants.size(); ++i) {
        std::string title = render::frame::panelLetter(i);
        if (plan.variants[i].scene.model.variant != title) title += ": " + plan.variants[i].scene.model.variant;
        out.titles.push_back(title);
      }
    } else {
      out.path += baseOf(first.model) + "-t" + timeForName(t) + ".png";
    }
    s.shots.push_back(std::move(out));
  }
  return s;
}

}  // namespace

std::vector<std::string> RenderPlan3::paths() const {
  std::vector<std::string> all;
  for (const VideoOutput3& v : videos) {
    all.push_back(v.path);
    all.push_back(v.posterPath);
    if (!v.framesPath.empty()) all.push_back(v.framesPath);
  }
  if (stills)
    for (const StillOutput& shot : stills->shots) all.push_back(shot.path);
  return all;
}

RenderPlan3 planVideos3(const LoadVariant3& load, const VideoRequest& r) {
  std::vector<render::scene3d::Scene> scenes =
      r.allVariants ? variantsOf(load(""), load) : std::vector<render::scene3d::Scene>{load(r.variant)};
  if (r.duration)
    for (const render::scene3d::Scene& s : scenes)
      if (const std::string over = sim::core::stepsOverLimit(s.model.dt, s.model.maxSteps, *r.duration); !over.empty())
        throw UsageError("--duration: " + over + "; choose a shorter video, or raise the scene's 'sim: {max_steps: N}'");
  boundFrames(scenes, r.duration, r.fps);
  RenderPlan3 plan = surveyed(std::move(scenes), r.size, r.fps, r.duration.value_or(-1.0));
  for (size_t i = 0; i < plan.variants.size(); ++i)
    plan.videos.push_back(videoOf(plan, i, r.root, r.duration.value_or(plan.variants[i].scene.model.duration), r.format, r.frames));
  return plan;
}

RenderPlan3 planStills3(const LoadVariant3& load, const StillRequest& r) {
  if (r.impacts) throw UsageError("--impacts: " + r.file + " is a 3D scene, and nothing collides in 3D; give times with --at");
  if (r.strobe.value_or(0) > 0) throw UsageError("--strobe: earlier poses are ghosted in 2D frames only");
  std::vector<render::scene3d::Scene> scenes;
  if (r.panels) {
    const std::vector<std::string> names = load("").model.variantNames;
    if (names.empty()) throw UsageError("--panels: " + r.file + " has no variants to put side by side");
    for (const std::string& name : names) scenes.push_back(load(name));
  } else {
    scenes.push_back(load(r.variant));
  }
  RenderPlan3 plan = surveyed(std::move(scenes), r.size, std::nullopt, -1.0);
  plan.stills = stillsOf(plan, r.times, r.panels, r.root);
  return plan;
}

RenderPlan3 planLecture3(const LoadVariant3& load, const LectureRequest& r) {
  const render::scene3d::Scene base = load("");
  std::vector<render::scene3d::Scene> scenes = variantsOf(base, load);
  boundFrames(scenes, std::nullopt, r.fps);
  RenderPlan3 plan = surveyed(std::move(scenes), r.size, r.fps, -1.0);
  plan.scene = base.model.name;
  for (size_t i = 0; i < plan.variants.size(); ++i)
    plan.videos.push_back(videoOf(plan, i, r.root, plan.variants[i].scene.model.duration, VideoFormat::Mp4, false));
  // the poll panels at the scene's `panels:` times, the default one moved to the shortest variant's duration
  std::vector<double> times = base.render.panels.times;
  double shortest = base.model.duration;
  for (const PlannedVariant3& v : plan.variants) shortest = std::min(shortest, v.scene.model.duration);
  if (base.render.panels.line == 0 && !times.empty()) times = {shortest};
  if (!times.empty()) plan.stills = stillsOf(plan, times, true, r.root);
  return plan;
}

}  // namespace render::video

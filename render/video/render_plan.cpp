#include "render/video/render_plan.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <type_traits>

#include "render/frame/energy_panel.h"
#include "render/frame/caption.h"
#include "render/frame/panel_camera.h"
#include "render/frame/panels.h"
#include "render/frame/pixel_draw_list.h"
#include "render/frame/quantity_text.h"
#include "render/frame/title_card.h"
#include "render/frame3d/energy3d.h"
#include "render/jobs/exit_status.h"
#include "render/video/output_names.h"
#include "sim/core/step_limit.h"
#include "sim/yaml/scene_error.h"

namespace render::video {
using namespace render::jobs;
using namespace render::frame3d;
using namespace render::draw;
using namespace render::frame;
using namespace render::scene;

namespace {

// the width of the energy panel beside a variant's frame, px, in each dimension's own layout
double panelBand(const Planar::Scene& def, const Planar::Survey& survey) {
  return EnergyPanel::bandPx(def, survey, def.render.height);
}
double panelBand(const Spatial::Scene& def, const Spatial::Survey& survey) {
  return EnergyPanel3d::bandPx(def, survey, def.render.height);
}

// the scene's variants, each read for itself, or the base scene itself when it has none
template <class D>
std::vector<typename D::Scene> variantsOf(typename D::Scene base, const LoadVariantOf<D>& load) {
  if (base.model.variantNames.empty()) return {std::move(base)};
  std::vector<typename D::Scene> scenes;
  for (const std::string& name : base.model.variantNames) scenes.push_back(load(name));
  return scenes;
}

// <root>/<scene>, where the scene's outputs go
template <class Model>
std::string directoryOf(const std::string& root, const Model& model) {
  return (std::filesystem::path(root) / model.name).string();
}

// "<scene>[-<variant>]", the base of a variant's file names
template <class Model>
std::string baseOf(const Model& model) {
  return outputBase(model.name, model.variant);
}

// the instants a variant's pictures will show, for its survey to keep its run at
template <class Scene>
using KeepAt = std::function<std::vector<double>(const Scene&)>;

// the instants of a video of `duration` s and of its poster: every frame's, those of slow-motion
// windows around impacts aside (not known before the survey; their frames step from the instant
// before), and each strobe ghost's
template <class Scene>
std::vector<double> videoInstants(const Scene& scene, double duration) {
  const render::scene::RenderDef& r = scene.render;
  const TimeMap map = timeMapFor(r, {}, duration);
  std::vector<double> instants;
  // the first frames only of a video longer than the states kept could hold (10⁷ frames: 80 MB of times)
  const long frames = std::min(map.frameCount(r.fps), render::scene::kKeptMostInstants);
  instants.reserve(static_cast<size_t>(frames) + static_cast<size_t>(r.strobe) + 2);
  for (long k = 0; k < frames; ++k) instants.push_back(map.simTime(static_cast<double>(k) / r.fps));
  const double poster = r.poll.question.empty() ? duration : 0.0;
  for (int i = 0; i < r.strobe; ++i) instants.push_back(poster * i / r.strobe);
  instants.push_back(poster);
  return instants;
}

// each of `times` and its strobe ghosts
std::vector<double> stillInstants(const std::vector<double>& times, int strobe) {
  std::vector<double> instants;
  for (double t : times) {
    for (int i = 0; i < strobe; ++i) instants.push_back(t * i / strobe);
    instants.push_back(t);
  }
  return instants;
}

// each variant at the size (and frame rate) asked for, surveyed from 0 to `until` (its duration when
// negative) and kept at the instants `keepAt` names: the one run of its world
template <class D>
RenderPlanOf<D> surveyed(std::vector<typename D::Scene> scenes, const std::optional<FrameSize>& size,
                         const std::optional<double>& fps, double until, const KeepAt<typename D::Scene>& keepAt = {}) {
  RenderPlanOf<D> plan;
  plan.scene = scenes.front().model.name;
  for (typename D::Scene& scene : scenes) {
    if (size) scene.render.width = size->width, scene.render.height = size->height;
    if (fps) scene.render.fps = *fps;
    try {
      // the kept states' bytes shared by the variants, all kept until the plan is written
      typename D::Survey survey =
          surveyRun(scene, until, keepAt ? keepAt(scene) : std::vector<double>{}, render::scene::kKeptRunBytes / scenes.size());
      // a view past what double arithmetic can draw is a bad scene, said before any frame
      if constexpr (std::is_same_v<D, Planar>) render::frame::checkView(scene, survey, cameraFor(scene, survey));
      plan.variants.push_back({std::move(scene), std::move(survey)});
    } catch (const sim::core::Diverged& d) {
      throw VariantDivergedOf<D>(d, scene.model, DrawStage::Planning);
    }
  }
  return plan;
}

// a card that cannot show its whole text (its font shrunk to the least) is refused before anything
// renders, at the text's line
template <class Scene>
void checkCards(const Scene& scene) {
  const render::scene::RenderDef& r = scene.render;
  if (!(r.titleCard > 0.0) && !(r.poll.answerCard > 0.0)) return;
  TextRenderer text;
  if (r.titleCard > 0.0) sceneCard(r, scene.model.name, scene.model.description, false, r.width, r.height, text);
  if (r.poll.answerCard > 0.0) sceneCard(r, scene.model.name, scene.model.description, true, r.width, r.height, text);
}

// the camera of variant `i`'s video: fitted over every variant the plan draws, so that a scene's
// videos show its variants at one scale and in one place (10b's body passing through the wall and
// bouncing off it, side by side on a slide), as its poll sheet does
template <class D>
typename D::Camera videoCamera(const RenderPlanOf<D>& plan, size_t i) {
  std::remove_cvref_t<decltype(plan.variants[i].survey.bounds)> bounds;
  for (const PlannedVariantOf<D>& v : plan.variants) bounds.add(v.survey.bounds);
  return cameraFor(plan.variants[i].scene, plan.variants[i].survey, bounds);
}

// the video of variant `i` over `duration` s of simulation, and its poster: at the end, or at the
// start where the scene asks a question (the poster stands beside the question on the page)
template <class D>
VideoOutputOf<D> videoOf(const RenderPlanOf<D>& plan, size_t i, const std::string& root, double duration, VideoFormat format,
                         bool frames) {
  const PlannedVariantOf<D>& v = plan.variants[i];
  const render::scene::RenderDef& r = v.scene.render;
  const std::string directory = directoryOf(root, v.scene.model);
  const std::string base = directory + "/" + baseOf(v.scene.model);
  checkCards(v.scene);
  // frame k at the simulation time of video time k / fps, for every k / fps < the video's length:
  // the title card, then `duration` stretched by the slow-motion windows (exactly `duration` without)
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
          .posterTime = r.poll.question.empty() ? duration : 0.0,
          .posterStrobe = r.strobe,
          .timeMap = std::move(map),
          .frameCount = count,
          .camera = videoCamera(plan, i)};
}

// what the stills show: the times asked for, or each variant's impacts
struct StillSpec {
  std::vector<double> times;
  bool impacts = false;
  bool panels = false;
  std::optional<int> strobe;
  std::string root;
  std::string file;                // named in messages
  std::optional<FrameSize> sheet;  // of a panel sheet: 1920 × 1080 unless asked
  std::string baseTitle;           // the base scene's render: {title}: a variant's own differs from it
  std::string baseVariantTitle;    // the base scene's top-level `title:`: a variant's own differs from it
  bool drawList = false;           // a draw list beside each still
};

// shot by shot, each variant at the same times, each inside every variant's duration
template <class D>
std::vector<std::vector<double>> atTimes(const RenderPlanOf<D>& plan, const std::vector<double>& times) {
  std::vector<std::vector<double>> instants;  // [shot][variant]
  for (double t : times) {
    for (const PlannedVariantOf<D>& v : plan.variants)
      if (t < 0.0 || t > v.scene.model.duration)
        throw UsageError("--at: " + timeForName(t) + " s is outside the scene's duration [0, " +
                         timeForName(v.scene.model.duration) + "]");
    instants.push_back(std::vector<double>(plan.variants.size(), t));
  }
  return instants;
}

// shot i: each variant at its i-th impact, or at its last when it has fewer
template <class D>
std::vector<std::vector<double>> atImpacts(const RenderPlanOf<D>& plan, const std::string& file) {
  size_t most = 0;
  for (const PlannedVariantOf<D>& v : plan.variants) {
    const ModelOf<D>& model = v.scene.model;
    if (v.survey.impactTimes.empty())
      throw UsageError("--impacts: " + file + (model.variant.empty() ? "" : " (variant " + model.variant + ")") +
                       " has no impacts in its " + timeForName(model.duration) +
                       " s; nothing collides there (use --at to choose times)");
    most = std::max(most, v.survey.impactTimes.size());
  }
  std::vector<std::vector<double>> instants;
  for (size_t i = 0; i < most; ++i) {
    std::vector<double> shot;
    for (const PlannedVariantOf<D>& v : plan.variants)
      shot.push_back(v.survey.impactTimes[std::min(i, v.survey.impactTimes.size() - 1)]);
    instants.push_back(shot);
  }
  return instants;
}

// the variant beside the widest energy panel: the shared camera leaves its band free
template <class D>
size_t widestPanel(const std::vector<typename D::Scene>& scenes, const std::vector<typename D::Survey>& surveys) {
  size_t widest = 0;
  double widestBand = -1.0;
  for (size_t i = 0; i < scenes.size(); ++i)
    if (const double band = panelBand(scenes[i], surveys[i]); band > widestBand) widest = i, widestBand = band;
  return widest;
}

// one camera for all panels, so that the variants compare at the same scale: over every variant's
// run, beside the widest energy panel among them; a 2D panel sheet's also holds every arrow, dot and
// body each panel draws over the run (panel_camera.h)
Planar::Camera sharedCamera(const std::vector<Planar::Scene>& scenes, const std::vector<Planar::Survey>& surveys, bool panels) {
  const size_t widest = widestPanel<Planar>(scenes, surveys);
  if (panels) return panelCamera(scenes, surveys, widest);
  Bounds bounds;
  for (const Planar::Survey& s : surveys) bounds.add(s.bounds);
  return cameraFor(scenes[widest], surveys[widest], bounds);
}
Spatial::Camera sharedCamera(const std::vector<Spatial::Scene>& scenes, const std::vector<Spatial::Survey>& surveys, bool) {
  const size_t widest = widestPanel<Spatial>(scenes, surveys);
  std::remove_cvref_t<decltype(surveys.front().bounds)> bounds;
  for (const Spatial::Survey& s : surveys) bounds.add(s.bounds);
  return cameraFor(scenes[widest], surveys[widest], bounds);
}

// the caption a scene's frames show, in each dimension
std::string captionFor(const Planar::Scene& s) { return captionOf(s); }
std::string captionFor(const Spatial::Scene& s) { return captionOf(s.render, s.model.description); }

// does `name` begin with the panel's `letter` as a word ("A", "A: center", "A (centre)"; not "Apple")?
bool lettered(const std::string& name, const std::string& letter) {
  if (name.compare(0, letter.size(), letter) != 0) return false;
  return name.size() == letter.size() || !std::isalnum(static_cast<unsigned char>(name[letter.size()]));
}

// "A: center": the panel's letter and the variant's `title:` (one of its own, not the base scene's),
// else its `render: {title}` where that differs from the base scene's, else its key; "A" alone for a
// variant named A, and a title that starts with its letter ("A: at the center") is not lettered
// again. At an impact, its time to the millisecond, as the frame's clock writes it
template <class Scene>
std::string panelTitle(size_t i, const Scene& variant, const StillSpec& spec, bool impacts, double t) {
  const std::string letter = panelLetter(i);
  const std::string& own = variant.render.poll.title;
  const std::string& card = variant.render.title;
  const std::string name = !own.empty() && own != spec.baseVariantTitle ? own
                           : !card.empty() && card != spec.baseTitle    ? card
                                                                        : variant.model.variant;
  std::string title = lettered(name, letter) ? name : letter + ": " + name;
  if (impacts) title += "  (t = " + timeToMs(t) + " s)";
  return title;
}

// a variant as a panel of a sheet draws it: its frame the grid's, its text the sheet's (at least a
// 40th of the sheet high), its caption left to the sheet, once under the grid
template <class Scene>
Scene asPanel(Scene scene, const PanelGrid& grid) {
  scene.render.width = grid.frameWidth, scene.render.height = grid.frameHeight;
  scene.render.fontSize = std::max(scene.render.fontSize, static_cast<double>(grid.textSize));
  // lines as thick as on a frame the sheet's height (3 px at 1080p), not the panel's
  if (!(scene.render.lineWidth > 0.0)) scene.render.lineWidth = grid.sheetHeight / 360.0;
  scene.render.caption.clear();
  scene.render.captionFromDescription = false;
  return scene;
}

// the grid of a sheet: for 2D scenes the one whose frames show the variants largest (each count of
// columns tried, the camera fitted over every variant's run beside the widest energy panel), so that a
// wide run is stacked and a tall one set side by side; the usual grid where it does as well. 3D: the
// usual grid
PanelGrid sheetGrid(const std::vector<Planar::Scene>& scenes, const std::vector<Planar::Survey>& surveys, int width, int height,
                    bool caption, int captionLines) {
  const PanelGrid usual = panelGrid(scenes.size(), width, height, caption, 0, captionLines);
  Bounds bounds;
  for (const Planar::Survey& s : surveys) bounds.add(s.bounds);
  const auto pixelSize = [&](const PanelGrid& grid) {
    std::vector<Planar::Scene> panels;
    for (const Planar::Scene& scene : scenes) panels.push_back(asPanel(scene, grid));
    const size_t widest = widestPanel<Planar>(panels, surveys);
    return cameraFor(panels[widest], surveys[widest], bounds).pixelSize();
  };
  PanelGrid best = usual;
  double bestSize = pixelSize(usual);
  for (int columns = 1; columns <= static_cast<int>(scenes.size()); ++columns) {
    if (columns == usual.columns) continue;
    try {
      const PanelGrid grid = panelGrid(scenes.size(), width, height, caption, columns, captionLines);
      // clearly larger (a tenth), or the usual grid stays
      if (const double size = pixelSize(grid); size < 0.9 * bestSize) best = grid, bestSize = size;
    } catch (const UsageError&) {
      // frames too small that way
    }
  }
  return best;
}
PanelGrid sheetGrid(const std::vector<Spatial::Scene>& scenes, const std::vector<Spatial::Survey>&, int width, int height,
                    bool caption, int captionLines) {
  return panelGrid(scenes.size(), width, height, caption, 0, captionLines);
}

// the stills of every variant of the plan, at the times or impacts of `spec`
template <class D>
StillsOf<D> stillsOf(const RenderPlanOf<D>& plan, const StillSpec& spec) {
  const typename D::Scene& first = plan.variants.front().scene;
  std::vector<typename D::Survey> surveys;
  std::vector<typename D::Scene> scenes;
  for (const PlannedVariantOf<D>& v : plan.variants) surveys.push_back(v.survey), scenes.push_back(v.scene);
  // on a sheet, the variants' arrows and energy bars are drawn at one scale too
  PanelGrid grid;
  std::string caption;
  if (spec.panels) {
    std::vector<typename D::Survey*> all;
    for (typename D::Survey& survey : surveys) all.push_back(&survey);
    shareScales(all);
    caption = captionFor(first);
    const int width = spec.sheet ? spec.sheet->width : kSheetWidth, height = spec.sheet ? spec.sheet->height : kSheetHeight;
    // the whole caption under the grid, in as many lines as it needs (a few)
    TextRenderer text;
    const int lines = caption.empty() ? 0 : sheetCaptionLines(caption, width, height, text);
    grid = sheetGrid(scenes, surveys, width, height, !caption.empty(), lines);
    for (typename D::Scene& scene : scenes) scene = asPanel(std::move(scene), grid);
  }
  const int strobe = spec.strobe.value_or(first.render.strobe);
  const std::vector<std::vector<double>> instants = spec.impacts ? atImpacts(plan, spec.file) : atTimes(plan, spec.times);
  StillsOf<D> s{.directory = directoryOf(spec.root, first.model),
                .scenes = scenes,
                .surveys = surveys,
                .panels = spec.panels,
                .grid = grid,
                .caption = caption,
                .strobe = strobe,
                .width = scenes.front().render.width,
                .height = scenes.front().render.height,
                .camera = sharedCamera(scenes, surveys, spec.panels),
                .shots = {}};
  std::vector<double> firsts;
  for (const std::vector<double>& shot : instants) firsts.push_back(shot[0]);
  const std::vector<std::string> timeNames = timesForNames(firsts);
  for (size_t shot = 0; shot < instants.size(); ++shot) {
    StillOutput out{.path = s.directory + "/", .instants = instants[shot], .titles = {}, .drawListPath = {}};
    const std::string impact = spec.impacts ? "-impact" + std::to_string(shot + 1) : "";
    const std::string at = "-t" + timeNames[shot];
    if (spec.panels) {
      out.path += panelsFileName(first.model.name, spec.impacts ? impact : at, strobe);
      for (size_t i = 0; i < plan.variants.size(); ++i)
        out.titles.push_back(panelTitle(i, plan.variants[i].scene, spec, spec.impacts, instants[shot][i]));
    } else {
      out.path += baseOf(first.model) + impact + at + strobeSuffix(strobe) + ".png";
    }
    if (spec.drawList) out.drawListPath = drawListPathFor(out.path);
    // the plan checked before anything is drawn: one file a still
    for (const StillOutput& other : s.shots)
      if (other.path == out.path)
        throw UsageError(out.path + ": two stills would be written to this file (--at gives the time " + timeNames[shot] +
                         " twice?); give each time once");
    s.shots.push_back(std::move(out));
  }
  return s;
}

// the scene's `panels:` for a lecture: the default time moved to the shortest variant's duration, and
// `impacts` refused at its line when a variant has none, before anything renders (times asked for are
// checked against each variant's duration when the variant is read)
template <class D>
render::scene::PanelsDef lecturePanels(const typename D::Scene& base, const RenderPlanOf<D>& plan, const std::string& file) {
  render::scene::PanelsDef panels = base.render.panels;
  const bool defaulted = panels.line == 0;
  double shortest = base.model.duration;
  for (const PlannedVariantOf<D>& v : plan.variants) shortest = std::min(shortest, v.scene.model.duration);
  if (defaulted && !panels.times.empty()) panels.times = {shortest};
  if (panels.impacts)
    for (const PlannedVariantOf<D>& v : plan.variants)
      if (v.survey.impactTimes.empty())
        throw sim::yaml::SceneError(file, panels.line, panels.column,
                                    "'panels: impacts' needs an impact in every variant, and variant '" + v.scene.model.variant +
                                        "' has none; give panel times instead, e.g. [0, " + timeForName(v.scene.model.duration) +
                                        "]");
  return panels;
}

template <class D>
RenderPlanOf<D> planVideosOf(const LoadVariantOf<D>& load, const VideoRequest& r) {
  std::vector<typename D::Scene> scenes =
      r.allVariants ? variantsOf<D>(load(""), load) : std::vector<typename D::Scene>{load(r.variant)};
  if (r.duration)
    for (const typename D::Scene& s : scenes)
      if (const std::string over = sim::core::stepsOverLimit(s.model.dt, s.model.maxSteps, *r.duration); !over.empty())
        throw UsageError("--duration: " + over + "; choose a shorter video, or raise the scene's 'sim: {max_steps: N}'");
  boundFrames(scenes, r.duration, r.fps);
  // each variant surveyed over its video's duration, which --duration sets for all, and kept at its frames
  const KeepAt<typename D::Scene> frames = [&](const typename D::Scene& s) {
    return videoInstants(s, r.duration.value_or(s.model.duration));
  };
  RenderPlanOf<D> plan = surveyed<D>(std::move(scenes), r.size, r.fps, r.duration.value_or(-1.0), frames);
  for (size_t i = 0; i < plan.variants.size(); ++i) {
    const double duration = r.duration.value_or(plan.variants[i].scene.model.duration);
    plan.videos.push_back(videoOf(plan, i, r.root, duration, r.format, r.frames));
  }
  return plan;
}

template <class D>
RenderPlanOf<D> planStillsOf(const LoadVariantOf<D>& load, const StillRequest& r) {
  std::vector<typename D::Scene> scenes;
  std::string baseTitle, baseVariantTitle;
  if (r.panels) {
    const typename D::Scene base = load("");
    const std::vector<std::string> names = base.model.variantNames;
    if (names.empty()) throw UsageError("--panels: " + r.file + " has no variants to put side by side");
    baseTitle = base.render.title;
    baseVariantTitle = base.render.poll.title;
    for (const std::string& name : names) scenes.push_back(load(name));
  } else {
    scenes.push_back(load(r.variant));
  }
  // --size is a single frame's, or with --panels the whole sheet's
  const KeepAt<typename D::Scene> stills = [&](const typename D::Scene& s) {
    return stillInstants(r.times, r.strobe.value_or(s.render.strobe));
  };
  RenderPlanOf<D> plan = surveyed<D>(std::move(scenes), r.panels ? std::nullopt : r.size, std::nullopt, -1.0, stills);
  plan.stills = stillsOf(plan, {r.times, r.impacts, r.panels, r.strobe, r.root, r.file, r.panels ? r.size : std::nullopt,
                                baseTitle, baseVariantTitle, r.drawList});
  return plan;
}

template <class D>
RenderPlanOf<D> planLectureOf(const LoadVariantOf<D>& load, const LectureRequest& r) {
  const typename D::Scene base = load("");
  // each variant surveyed once, over its duration: the video's and the panels' survey alike
  std::vector<typename D::Scene> scenes = variantsOf<D>(base, load);
  boundFrames(scenes, std::nullopt, r.fps);
  const KeepAt<typename D::Scene> pictures = [&](const typename D::Scene& s) {
    std::vector<double> instants = videoInstants(s, s.model.duration);
    const std::vector<double> panels = stillInstants(base.render.panels.times, s.render.strobe);
    instants.insert(instants.end(), panels.begin(), panels.end());
    return instants;
  };
  RenderPlanOf<D> plan = surveyed<D>(std::move(scenes), r.size, r.fps, -1.0, pictures);
  plan.scene = base.model.name;
  for (size_t i = 0; i < plan.variants.size(); ++i)
    plan.videos.push_back(videoOf(plan, i, r.root, plan.variants[i].scene.model.duration, VideoFormat::Mp4, false));
  // then the poll panels, as `snapshot --panels` draws them
  const render::scene::PanelsDef panels = lecturePanels(base, plan, r.file);
  if (!panels.times.empty() || panels.impacts)
    plan.stills = stillsOf(plan, {panels.times, panels.impacts, true, std::nullopt, r.root, r.file, r.size, base.render.title,
                                  base.render.poll.title});
  return plan;
}

}  // namespace

template <class D>
std::vector<std::string> RenderPlanOf<D>::paths() const {
  std::vector<std::string> all;
  for (const VideoOutputOf<D>& v : videos) {
    all.push_back(v.path);
    all.push_back(v.posterPath);
    if (!v.framesPath.empty()) all.push_back(v.framesPath);
  }
  if (stills)
    for (const StillOutput& shot : stills->shots) {
      all.push_back(shot.path);
      if (!shot.drawListPath.empty()) all.push_back(shot.drawListPath);
    }
  return all;
}
template struct RenderPlanOf<Planar>;
template struct RenderPlanOf<Spatial>;

RenderPlan planVideos(const LoadVariant& load, const VideoRequest& r) { return planVideosOf<Planar>(load, r); }
RenderPlan planStills(const LoadVariant& load, const StillRequest& r) { return planStillsOf<Planar>(load, r); }
RenderPlan planLecture(const LoadVariant& load, const LectureRequest& r) { return planLectureOf<Planar>(load, r); }

RenderPlan3d planVideos3d(const LoadVariant3d& load, const VideoRequest& r) { return planVideosOf<Spatial>(load, r); }

RenderPlan3d planStills3d(const LoadVariant3d& load, const StillRequest& r) {
  if (r.strobe.value_or(0) > 0) throw UsageError("--strobe: earlier poses are ghosted in 2D frames only");
  if (r.drawList)
    throw UsageError("--draw-list: " + r.file + " is a 3D scene; draw lists in pixels are written for 2D scenes only");
  return planStillsOf<Spatial>(load, r);
}

RenderPlan3d planLecture3d(const LoadVariant3d& load, const LectureRequest& r) { return planLectureOf<Spatial>(load, r); }

}  // namespace render::video

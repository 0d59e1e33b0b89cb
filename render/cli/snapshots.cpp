#include "render/cli/snapshots.h"

#include <algorithm>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/space3d.h"
#include "render/draw/png_io.h"
#include "render/frame/energy_panel.h"
#include "render/frame/panels.h"
#include "render/frame/scene_run.h"
#include "render/scene/scene_style.h"

namespace render::cli {
using namespace render::draw;
using namespace render::frame;
using namespace render::scene;

namespace {

// one variant of the scene, with the command line's overrides
struct Variant {
  render::scene::Scene def;
  RunSurvey survey;
};

}  // namespace

void writeSnapshots(const SnapshotOptions& o, const Wrote& wrote) {
  if (o.times.empty() == !o.impacts) throw UsageError("give the times with --at T1,T2,... or ask for --impacts (one of them)");
  if (o.panels && !o.variant.empty())
    throw UsageError("--panels shows every variant side by side; leave out --variant");
  if (o.strobe && (*o.strobe < 0 || *o.strobe > 100)) throw UsageError("--strobe: give a number of ghosts from 0 to 100");
  std::optional<FrameSize> size;
  if (!o.size.empty()) size = parseSize(o.size);
  if (isSceneFile3d(o.scene)) return writeSnapshots3d(o, size, wrote);

  // the variants: every one side by side, or the one asked for (or the base scene)
  std::vector<std::string> names = {o.variant};
  if (o.panels) {
    names = o.load().model().variantNames;
    if (names.empty()) throw UsageError("--panels: " + o.scene + " has no variants to put side by side");
  }
  std::vector<Variant> variants;
  for (const std::string& name : names) {
    SceneOptions one = o;
    one.variant = name;
    Variant v{one.load().scene, {}};
    if (size) v.def.render.width = size->width, v.def.render.height = size->height;
    v.survey = surveyRun(v.def);
    variants.push_back(std::move(v));
  }
  // side by side, the variants' arrows and energy bars are drawn at one scale too
  if (o.panels) {
    std::vector<RunSurvey*> surveys;
    for (Variant& v : variants) surveys.push_back(&v.survey);
    shareScales(surveys);
  }
  const render::scene::Scene& first = variants.front().def;
  const int strobe = o.strobe.value_or(first.render.strobe);

  // the instants: per panel, per variant (the same --at times for all; each variant's own impacts)
  std::vector<std::vector<double>> instants;  // [shot][variant]
  if (!o.impacts) {
    for (double t : o.times) {
      for (const Variant& v : variants)
        if (t < 0.0 || t > v.def.model.duration)
          throw UsageError("--at: " + timeForName(t) + " s is outside the scene's duration [0, " +
                           timeForName(v.def.model.duration) + "]");
      instants.push_back(std::vector<double>(variants.size(), t));
    }
  } else {
    size_t most = 0;
    for (const Variant& v : variants) {
      if (v.survey.impactTimes.empty())
        throw UsageError("--impacts: " + o.scene + (v.def.model.variant.empty() ? "" : " (variant " + v.def.model.variant + ")") +
                         " has no impacts in its " + timeForName(v.def.model.duration) +
                         " s; nothing collides there (use --at to choose times)");
      most = std::max(most, v.survey.impactTimes.size());
    }
    // shot i: each variant at its i-th impact, or at its last when it has fewer
    for (size_t i = 0; i < most; ++i) {
      std::vector<double> shot;
      for (const Variant& v : variants) shot.push_back(v.survey.impactTimes[std::min(i, v.survey.impactTimes.size() - 1)]);
      instants.push_back(shot);
    }
  }

  // one camera for all panels, so that the variants compare at the same scale: over every variant's
  // run, beside the widest energy panel among them
  Bounds bounds;
  const Variant* widest = &variants.front();
  double widestBand = -1.0;
  for (const Variant& v : variants) {
    bounds.add(v.survey.bounds);
    const double band = EnergyPanel::bandPx(v.def, v.survey, v.def.render.height);
    if (band > widestBand) widest = &v, widestBand = band;
  }
  const Camera camera = cameraFor(widest->def, widest->survey, bounds);
  const std::string dir = outputDirectory(o.output, first.model.name);
  GlContext gl(first.render.width, first.render.height);
  TextRenderer text;
  for (size_t shot = 0; shot < instants.size(); ++shot) {
    std::vector<Image> frames;
    std::vector<std::string> titles;
    for (size_t i = 0; i < variants.size(); ++i) {
      const Variant& v = variants[i];
      const double t = instants[shot][i];
      // a fresh run per picture: the strobe ghosts and the trails start from t = 0
      SceneRun run(v.def, camera, v.survey, &gl, &text);
      frames.push_back(run.frameAt(t, strobe));
      // "A: center", or just "A" for a variant named A
      std::string title = panelLetter(i);
      if (v.def.model.variant != title) title += ": " + v.def.model.variant;
      if (o.impacts) title += "  (t = " + timeForName(t) + " s)";
      titles.push_back(title);
    }
    std::string path;
    if (o.panels) {
      const std::string when = o.impacts ? "-impact" + std::to_string(shot + 1) : "-t" + timeForName(instants[shot][0]);
      path = dir + "/" + panelsFileName(first.model.name, when, strobe);
      const Style style = makeStyle(first, first.render.height);
      writePng(composePanels(frames, titles, style, text), path);
    } else {
      const std::string when = (o.impacts ? "-impact" + std::to_string(shot + 1) : "") + "-t" + timeForName(instants[shot][0]);
      path = dir + "/" + outputBase(first.model) + when + strobeSuffix(strobe) + ".png";
      writePng(frames.front(), path);
    }
    wrote(path);
  }
}

}  // namespace render::cli

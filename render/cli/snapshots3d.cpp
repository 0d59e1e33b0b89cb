// `rigidreel snapshot` of a 3D scene: still frames in perspective at exact times, one PNG each, or
// every variant side by side at one camera and one scale (the poll slide), named as 2D stills are.
#include <algorithm>

#include "render/cli/commands.h"
#include "render/cli/space3d.h"
#include "render/draw/png_io.h"
#include "render/frame/panels.h"
#include "render/frame3d/energy3.h"
#include "render/frame3d/scene_run3.h"

namespace render::cli {
using namespace render::frame3d;

namespace {

struct Variant3 {
  render::scene3d::Scene def;
  RunSurvey3 survey;
};

}  // namespace

void writeSnapshots3d(const SnapshotOptions& o, const std::optional<FrameSize>& size, const Wrote& wrote) {
  if (o.impacts) throw UsageError("--impacts: " + o.scene + " is a 3D scene, and nothing collides in 3D; give times with --at");
  if (o.strobe.value_or(0) > 0) throw UsageError("--strobe: earlier poses are ghosted in 2D frames only");
  // the variants: every one side by side, or the one asked for (or the base scene)
  std::vector<std::string> names = {o.variant};
  if (o.panels) {
    names = o.load3().model().variantNames;
    if (names.empty()) throw UsageError("--panels: " + o.scene + " has no variants to put side by side");
  }
  std::vector<Variant3> variants;
  variants.reserve(names.size());
  const sim::scene3d::SceneDef* running = nullptr;  // the variant simulated now, for a divergence's message
  try {
    for (const std::string& name : names) {
      SceneOptions one = o;
      one.variant = name;
      Variant3 v{one.load3().scene, {}};
      if (size) v.def.render.width = size->width, v.def.render.height = size->height;
      for (double t : o.times)
        if (t < 0.0 || t > v.def.model.duration)
          throw UsageError("--at: " + timeForName(t) + " s is outside the scene's duration [0, " +
                           timeForName(v.def.model.duration) + "]");
      variants.push_back(std::move(v));
      running = &variants.back().def.model;
      variants.back().survey = surveyRun(variants.back().def);
    }
    // side by side: one scale for arrows and bars, one camera over every variant's run beside the
    // widest energy panel
    std::vector<RunSurvey3*> surveys;
    for (Variant3& v : variants) surveys.push_back(&v.survey);
    if (o.panels) shareScales(surveys);
    Box3 bounds;
    const Variant3* widest = &variants.front();
    double widestBand = -1.0;
    for (const Variant3& v : variants) {
      bounds.add(v.survey.bounds);
      const double band = EnergyPanel3::bandPx(v.def, v.survey, v.def.render.height);
      if (band > widestBand) widest = &v, widestBand = band;
    }
    const Camera3 camera = cameraFor(widest->def, widest->survey, bounds);
    const render::scene3d::Scene& first = variants.front().def;
    const std::string dir = outputDirectory(o.output, first.model.name);
    GlContext gl(first.render.width, first.render.height);
    TextRenderer text;
    for (double t : o.times) {
      std::vector<Image> frames;
      std::vector<std::string> titles;
      for (size_t i = 0; i < variants.size(); ++i) {
        // a fresh run per picture: the trails and paths start from t = 0
        running = &variants[i].def.model;
        SceneRun3 run(variants[i].def, camera, variants[i].survey, &gl, &text);
        frames.push_back(run.frameAt(t));
        std::string title = render::frame::panelLetter(i);
        if (variants[i].def.model.variant != title) title += ": " + variants[i].def.model.variant;
        titles.push_back(title);
      }
      std::string path;
      if (o.panels) {
        path = dir + "/" + panelsFileName(first.model.name, "-t" + timeForName(t), 0);
        writePng(render::frame::composePanels(frames, titles, render::scene3d::makeStyle(first, first.render.height), text), path);
      } else {
        path = dir + "/" + outputBase(first.model.name, first.model.variant) + "-t" + timeForName(t) + ".png";
        writePng(frames.front(), path);
      }
      wrote(path);
    }
  } catch (const sim::world3d::Diverged& d) {
    throw std::runtime_error(divergedMessage(o.scene, *running, d));
  }
}

}  // namespace render::cli

#include "render/golden/golden_run.h"

#include <algorithm>
#include <optional>

#include "render/frame/scene_run.h"
#include "render/frame/survey.h"
#include "render/golden/golden_drawing.h"
#include "render/scene/scene_style.h"
#include "render/video/output_names.h"
#include "sim/world/diagnostics.h"

namespace render::golden {
using namespace render::trace;

namespace {

TraceSample sampleOf(const sim::world::World& w, size_t i) {
  const sim::core::Body& b = w.bodies[i];
  return {w.time, b.x.x(), b.x.y(), b.angle, b.v.x(), b.v.y(), b.omega, sim::world::kineticEnergy(b).total(), 0};
}

}  // namespace

std::string frameName(double t) { return "frame-t" + render::video::timeForName(t); }

GoldenRun runGolden(const render::scene::Scene& original, const GoldenDef& golden, const GoldenTimes* asked, bool pixels) {
  const render::scene::Scene scene = atGoldenSize(original, golden);
  GoldenRun run = goldenRunOf(scene.model, false);
  const auto surveyed = surveyGolden(scene, golden, asked, [](const auto&... a) { return render::frame::surveyRun(a...); });
  const GoldenTimes& times = surveyed.times;
  const render::draw::Camera camera = render::frame::cameraFor(scene, surveyed.survey);
  const render::draw::Style style = render::scene::makeStyle(scene, golden.height);
  // every instant once: a frame's time is also a checkpoint
  const std::vector<double>& instants = times.checkpoints;
  std::vector<bool> pictured(instants.size());
  for (size_t i = 0; i < instants.size(); ++i)
    pictured[i] = std::binary_search(times.frames.begin(), times.frames.end(), instants[i]);
  run.checkpoints.resize(instants.size());
  std::vector<std::optional<GoldenFrame>> frames(instants.size());
  // frames named with as many digits as tell every two apart (0.5 and 0.5000004 are two files)
  const std::vector<std::string> names = render::video::timesForNames(times.frames);
  GoldenDrawing drawing(golden, pixels, run);
  render::frame::SceneRun sceneRun(scene, camera, surveyed.survey, drawing.gl(), drawing.text());
  sceneRun.shotsAt(instants, pictured, [&](size_t i, const render::frame::SceneRun::Shot& shot) {
    Checkpoint& c = run.checkpoints[i];
    c.t = instants[i];
    c.hash = sim::world::stateHash(shot.world);
    for (size_t b = 0; b < shot.world.bodies.size(); ++b) c.bodies.push_back(sampleOf(shot.world, b));
    if (pictured[i])
      frames[i] = GoldenFrame{
          instants[i],
          "frame-t" + names[std::lower_bound(times.frames.begin(), times.frames.end(), instants[i]) - times.frames.begin()],
          drawnFrame(shot.drawList, style, camera), shot.frame};
  });
  for (std::optional<GoldenFrame>& f : frames)
    if (f) run.frames.push_back(std::move(*f));
  return run;
}

}  // namespace render::golden

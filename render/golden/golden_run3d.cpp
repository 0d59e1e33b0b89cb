#include "render/golden/golden_run3d.h"

#include <algorithm>

#include "render/frame3d/scene_run3d.h"
#include "render/frame3d/survey3d.h"
#include "render/golden/drawn_frame3d.h"
#include "render/golden/golden_drawing.h"
#include "render/golden/sample3d.h"
#include "sim/world3d/diagnostics.h"

namespace render::golden {

GoldenRun runGolden(const render::scene3d::Scene& original, const GoldenDef& golden, const GoldenTimes* asked, bool pixels) {
  const render::scene3d::Scene scene = atGoldenSize(original, golden);
  GoldenRun run = goldenRunOf(scene.model, true);
  const auto [survey, times] =
      surveyGolden(scene, golden, asked, [](const auto&... a) { return render::frame3d::surveyRun(a...); });
  const render::draw3d::Camera3d camera = render::frame3d::cameraFor(scene, survey);
  const render::draw::Style style = render::scene3d::makeStyle(scene, golden.height);
  GoldenDrawing drawing(golden, pixels, run);
  render::frame3d::SceneRun3d sceneRun(scene, camera, survey, drawing.gl(), drawing.text());
  // every instant once, in time order: a frame's time is also a checkpoint
  for (double t : times.checkpoints) {
    const render::draw3d::DrawList3d list = sceneRun.drawListAt(t);
    const sim::world3d::World& world = sceneRun.world();
    Checkpoint c{t, sim::world3d::stateHash(world), {}};
    for (const sim::world3d::Body& b : world.bodies) c.bodies.push_back(sampleOf(b, world.time));
    run.checkpoints.push_back(std::move(c));
    if (!std::binary_search(times.frames.begin(), times.frames.end(), t)) continue;
    GoldenFrame f{t, frameName(t), drawnFrame3d(list, style, golden.width, golden.height), {}};
    if (pixels) f.image = sceneRun.frameAt(t);
    run.frames.push_back(std::move(f));
  }
  return run;
}

}  // namespace render::golden

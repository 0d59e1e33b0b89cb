// One run of a 3D scene variant for a golden record, as golden_run.h is for 2D: the world advanced
// once, at each checkpoint its state hash and trace rows (the 3D columns), at each golden time its
// draw list (drawn_frame3d.h) and frame.
#pragma once

#include "render/golden/golden_run.h"
#include "render/scene3d/scene.h"
#include "sim/world3d/world.h"

namespace render::golden {

// the run at `times`, or (null) at those its golden: block asks for (goldenTimes, from the survey the
// drawing needs anyway), frames at the golden size; without `pixels` no GL is loaded. Throws
// sim::core::Diverged, std::runtime_error (GL).
GoldenRun runGolden(const render::scene3d::Scene& scene, const GoldenDef& golden, const GoldenTimes* times, bool pixels);

}  // namespace render::golden

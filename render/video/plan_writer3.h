// The render plan of a 3D scene carried out, as writePlan does for 2D: each video recorded in
// perspective with its poster, then the stills, every file complete before it is named.
#pragma once

#include "render/video/plan_writer.h"
#include "render/video/render_plan3.h"

namespace render::video {

// writes every output of `plan` in the order of plan.paths(), telling `wrote` each. Throws as
// writePlan, with VariantDiverged3 for a divergence
void writePlan3(const RenderPlan3& plan, bool quiet, const Wrote& wrote);

}  // namespace render::video

// Whether a body hides a point from the camera: the overlay of a 3D frame is drawn over the shaded
// solids without their depth, so a contact point behind a box would show through it as if in front.
#pragma once

#include <vector>

#include "sim/world3d/body.h"

namespace render::frame3d {

// whether the segment from `eye` to `point` passes through the inside of a body: its solid shrunk by
// `skin` (m; at most a quarter of the body's least half-size), so that a point on a body's own
// surface, or pressed a little into it, is not hidden by that body
bool hiddenByBodies(const sim::world3d::Vec3& eye, const sim::world3d::Vec3& point, const std::vector<sim::world3d::Body>& bodies,
                    double skin);

}  // namespace render::frame3d

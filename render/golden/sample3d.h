// A 3D body's state as a trace row holds it (trace_csv.h's render::trace::TraceSample with its 3D coordinates), and
// the one error of orientation the golden check and compare take: the angle between two rotations.
#pragma once

#include "render/trace/trace_csv.h"
#include "sim/world3d/body.h"

namespace render::golden {

// the body's state at time t, its kinetic energy with it
render::trace::TraceSample sampleOf(const sim::world3d::Body& body, double t);

// rad: the rotation from e's orientation to a's (q and −q alike), 2 atan2(|v|, |w|) of e⁻¹ a =
// (w, v), exact for small angles where the acos of a dot product is not
double rotationBetween(const render::trace::TraceSample& a, const render::trace::TraceSample& e);

}  // namespace render::golden

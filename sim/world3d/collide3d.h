// Pure contact functions in 3D: a box, a sphere or an ellipsoid against a static plane, and two
// spheres. Each writes the points within `margin` of touching (separation ≤ margin), in the
// notes' terms: where the body's surface meets the obstacle, and how far apart they are along n̂.
#pragma once

#include "sim/world3d/contact3d.h"

namespace sim::world3d {

// the points of `shape` posed at `s` within `margin` of the plane, into out; how many. A box: its
// corners (all four of a face lying flat); a sphere: its lowest point; an ellipsoid: its support
// point against the normal, x + R A² d/|A d| with d = −Rᵀ n̂ and A its semi-axes
int planeContact(const Shape& shape, const BodyState& s, const Plane& plane, double margin, ContactPoint3 out[kMaxContactPoints]);

// two spheres (radii ra, rb) within `margin`: the point midway between their surfaces on the line of
// centers, the normal from B to A; false when further apart
bool sphereContact(const BodyState& a, double ra, const BodyState& b, double rb, double margin, ContactPoint3& out, Vec3& normal);

}  // namespace sim::world3d

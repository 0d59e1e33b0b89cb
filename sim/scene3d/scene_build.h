// The 3D World built from a scene's definitions.
#pragma once

#include "sim/scene3d/scene_def.h"
#include "sim/world3d/world.h"

namespace sim::scene3d {

// a body's mass and inertia: those given, the rest from the shape filled at `density` (or at the
// density that gives the mass that is given, when only the mass is)
sim::world3d::MassProperties massProperties(const BodyDef& body);
// the body at its start state; throws std::invalid_argument when its mass properties are no solid's
sim::world3d::Body buildBody(const BodyDef& body);
// the world of the scene at t = 0 (the reader has checked every name and value)
sim::world3d::World buildWorld(const SceneDef& scene);

}  // namespace sim::scene3d

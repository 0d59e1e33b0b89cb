// From definitions to a World: mass properties, the centroid shift, names resolved to indices.
#pragma once

#include "sim/scene/scene_def.h"
#include "sim/world/world.h"

namespace sim::scene {

// the definitions must be valid (the loader checks them); body i of the world is def.bodies[i]
sim::world::World buildWorld(const SceneDef& def);

// a body's mass properties as the scene gives them: shape and density unless given outright
struct MassProperties {
  double mass = 0.0;
  double inertia = 0.0;
  sim::core::Vec2 centroid = sim::core::Vec2::Zero();  // in the coordinates the shape was written in
};
MassProperties massProperties(const BodyDef& def);

}  // namespace sim::scene

// What a scene's model holds alike in 2D and 3D, generic over the dimension's vector, body and
// expect entry: its heading, the world's gravity and default coefficients, the step, the collision
// method and its iterations, and the lists of bodies, forces, events and expect entries.
// sim/scene's and sim/scene3d's SceneDef add their own keys (plain definitions: no world sees them).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/core/collision_methods.h"
#include "sim/core/force_defs.h"
#include "sim/core/settings.h"

namespace sim::core {

template <class Vec, class Body, class Expect>
struct SceneDefOf {
  std::string name;
  std::string description;
  std::string variant;  // the variant merged in, empty for the base scene
  std::vector<std::string> variantNames;
  double duration = settings::kDefaultDuration;
  Vec gravity = Vec::Zero();
  double restitution = settings::kDefaultRestitution;  // c_r of every body (and 3D plane) that names none
  // μ of every body that names none; unset, the default (0) is not a μ the scene named, and a pair
  // with a body that names one takes that body's (sim::world::combinedFriction)
  std::optional<double> friction;
  double dt = settings::kDefaultDt;
  double maxSteps = settings::kDefaultMaxSteps;  // the most steps a run may take (sim: max_steps)
  CollisionMethod collisions = CollisionMethod::Auto;
  // where `sim: {collisions}` is written (line 0: not in the file, e.g. set on the command line)
  SourceLoc collisionsLoc;
  int velocityIterations = settings::kVelocityIterations;  // the sequential solver's (sim: iterations)
  int positionIterations = settings::kPositionIterations;
  std::vector<Body> bodies;
  std::vector<PointForceDefOf<Vec>> pointForces;
  std::vector<SpringDefOf<Vec>> springs;
  std::vector<DragDef> drags;
  std::vector<EventDefOf<Vec>> events;
  std::vector<Expect> expects;

  // what a world's definition takes from the model alike in 2D and 3D (each buildWorld adds its
  // own keys): the step, gravity, and the collision method with its iterations
  template <class WorldDef>
  void defineRun(WorldDef& w) const {
    w.dt = dt;
    w.forces.gravity = gravity;
    w.collisions = collisions;
    w.velocityIterations = velocityIterations;
    w.positionIterations = positionIterations;
  }

  // index of the body with this name, or -1 (a scan: for one lookup)
  int bodyIndex(const std::string& name) const {
    for (size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i].name == name) return static_cast<int>(i);
    return -1;
  }

  // every body's index by its name: for lookups of many entries, in one pass
  std::unordered_map<std::string, int> bodyIndices() const {
    std::unordered_map<std::string, int> out;
    for (size_t i = 0; i < bodies.size(); ++i) out.emplace(bodies[i].name, static_cast<int>(i));
    return out;
  }
};

}  // namespace sim::core

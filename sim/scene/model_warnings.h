// What a scene asks for that the collision method it names leaves out (method_models.h's table),
// said at the key that chose it: friction under a method whose contacts have none while bodies
// slide or rest, the scene's integrator under a method that integrates by its own. `auto` is never
// warned of: it picks a method that models what the scene sets up, and switches when contact
// persists (World::step).
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene_def.h"

namespace sim::scene {

struct ModelWarning {
  sim::core::SourceLoc loc;  // the key's place; line 0 when the value came from the command line
  std::string setting;       // the key as the scene writes it: "collisions" or "integrator"
  std::string value;         // its value, as written: "event", "rk4"
  std::string message;       // what the method leaves out, and what to use instead
};

std::vector<ModelWarning> modelWarnings(const SceneDef& def);

}  // namespace sim::scene

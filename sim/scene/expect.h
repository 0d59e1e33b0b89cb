// The closed-form answers of a scene's `expect` entries, compared with a simulated World.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene_def.h"
#include "sim/world/world.h"

namespace sim::scene {
using namespace sim::core;
using namespace sim::collision;
using namespace sim::world;

struct CheckResult {
  double time = 0.0;
  std::string quantity;  // e.g. "bar.velocity", "total_energy"
  std::vector<double> expected, actual;
  double error = 0.0;    // Euclidean norm of actual − expected
  double tolerance = 0.0;
  bool passed() const { return error <= tolerance; }
};

// every quantity of one entry, for a world already at the entry's time
std::vector<CheckResult> evaluate(const ExpectDef& expect, const SceneDef& def, const World& world);

// runs the scene's world through every expect entry in time order
std::vector<CheckResult> runExpects(const SceneDef& def, World& world);
// the same on a world built from the definitions
std::vector<CheckResult> runExpects(const SceneDef& def);

}  // namespace sim::scene

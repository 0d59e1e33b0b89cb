// The closed-form answers of a scene's `expect` entries, compared with a simulated World.
#pragma once

#include <string>
#include <vector>

#include "sim/core/check_result.h"
#include "sim/scene/scene_def.h"
#include "sim/world/world.h"

namespace sim::scene {

// every quantity of one entry, for a world already at the entry's time
// (`indices`: the scene's bodyIndices(), when many entries are evaluated; else each name is scanned for)
std::vector<sim::core::CheckResult> evaluate(const ExpectDef& expect, const SceneDef& def, const sim::world::World& world,
                                             const std::unordered_map<std::string, int>* indices = nullptr);

// runs the scene's world through every expect entry in time order on its own step grid (an entry
// between two steps is evaluated on a copy advanced to its time; `observer`, if any, sees every
// step of the run: a progress line). The world is left at its last step by the last entry.
std::vector<sim::core::CheckResult> runExpects(const SceneDef& def, sim::world::World& world,
                                               sim::world::StepObserver* observer = nullptr);
// the same on a world built from the definitions
std::vector<sim::core::CheckResult> runExpects(const SceneDef& def);

}  // namespace sim::scene

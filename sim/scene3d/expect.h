// The closed-form answers of a 3D scene's `expect` entries, compared with a simulated World: the
// state at an instant, and what the run up to it measures (precession rates, the flip period).
#pragma once

#include <vector>

#include "sim/core/check_result.h"
#include "sim/scene3d/scene_def.h"
#include "sim/world3d/measures.h"
#include "sim/world3d/world.h"

namespace sim::scene3d {

// every quantity of one entry, for a world at the entry's time; `measures` followed each body from
// t = 0 (by body index)
// (`indices`: the scene's bodyIndices(), when many entries are evaluated; else each name is scanned for)
std::vector<sim::core::CheckResult> evaluate(const ExpectDef& expect, const SceneDef& def, const sim::world3d::World& world,
                                             const std::vector<sim::world3d::FreeBodyMeasures>& measures,
                                             const std::unordered_map<std::string, int>* indices = nullptr);

// runs the scene's world from t = 0 through every expect entry in time order, measuring as it goes
// (`observer`, if any, sees every step: a progress line)
std::vector<sim::core::CheckResult> runExpects(const SceneDef& def, sim::world3d::World& world,
                                               sim::world3d::StepObserver* observer = nullptr);
// the same on a world built from the definitions
std::vector<sim::core::CheckResult> runExpects(const SceneDef& def);

}  // namespace sim::scene3d

// Which 3D body pairs a scene's contacts leave unmodeled: contacts between bodies are modeled for
// two spheres alone (sim/world3d/collide3d.h), so any other pair that could meet, in a scene whose
// collision method acts on bodies, would pass through each other unseen.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "sim/scene3d/scene_def.h"

namespace sim::scene3d {

// the first pair (earlier body, later body) that could meet and has no contact model, in body order,
// or none: none under `collisions: none`, nor under `auto` with no plane and fewer than two spheres
// (nothing then to collide, so auto chooses none)
std::optional<std::pair<int, int>> unmodeledPair(const SceneDef& scene);
// why such a pair is refused, and what to do
std::string unmodeledPairMessage(const std::string& earlier, const std::string& later);

}  // namespace sim::scene3d

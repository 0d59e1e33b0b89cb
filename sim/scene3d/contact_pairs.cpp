#include "sim/scene3d/contact_pairs.h"

#include <algorithm>

namespace sim::scene3d {

std::optional<std::pair<int, int>> unmodeledPair(const SceneDef& scene) {
  using sim::core::CollisionMethod;
  using sim::world3d::ShapeKind;
  if (scene.collisions == CollisionMethod::None) return std::nullopt;
  const auto isSphere = [](const BodyDef& b) { return b.shape.kind == ShapeKind::Sphere; };
  const long spheres = std::count_if(scene.bodies.begin(), scene.bodies.end(), isSphere);
  if (scene.collisions == CollisionMethod::Auto && scene.planes.empty() && spheres < 2) return std::nullopt;
  // the earlier body a later one is paired with: the first body, or the latest sphere so far
  int other = -1;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
    const BodyDef& b = scene.bodies[i];
    if (other >= 0 && !(isSphere(b) && isSphere(scene.bodies[other]))) return std::make_pair(other, i);
    if (other < 0 || isSphere(scene.bodies[other])) other = i;
  }
  return std::nullopt;
}

std::string unmodeledPairMessage(const std::string& earlier, const std::string& later) {
  return "3D contacts between bodies are modeled for two spheres only, and '" + later + "' and '" + earlier +
         "' would pass through each other; make them spheres, keep one body, or set 'sim: {collisions: none}'";
}

}  // namespace sim::scene3d

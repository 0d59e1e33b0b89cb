#include "sim/world3d/method_models3d.h"

#include <stdexcept>

namespace sim::world3d {
using sim::core::CollisionMethod;

CollisionMethod leastMethodFor3(unsigned needs) {
  static constexpr CollisionMethod kOrder[] = {CollisionMethod::None, CollisionMethod::Event, CollisionMethod::Sequential};
  return sim::core::leastMethodFor(kMethodModels3d, kOrder, needs);
}

std::unique_ptr<Method3> makeMethod3(CollisionMethod method) {
  switch (method) {
    case CollisionMethod::Auto:  // resolved by World::start
    case CollisionMethod::None: return makeFreeMotion3();
    case CollisionMethod::Event: return makeEventStepper3();
    case CollisionMethod::Sequential: return makeSequentialSolver3();
    case CollisionMethod::Isolated:
    case CollisionMethod::SoftStep: break;
  }
  throw std::invalid_argument("3D scenes take the collision methods none, event, sequential and auto");
}

}  // namespace sim::world3d

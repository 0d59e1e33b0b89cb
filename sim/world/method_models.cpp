#include "sim/world/method_models.h"

#include <stdexcept>

namespace sim::world {

using namespace sim::core;
const MethodModel& methodModel(CollisionMethod method) {
  if (const MethodModel* row = sim::core::findMethod(kMethodModels, method)) return *row;
  throw std::logic_error("methodModel: 'auto' has no row of its own; resolve it first");
}

CollisionMethod leastMethodFor(unsigned needs) {
  static constexpr CollisionMethod kOrder[] = {CollisionMethod::None, CollisionMethod::Event, CollisionMethod::Sequential};
  return sim::core::leastMethodFor(kMethodModels, kOrder, needs);
}

}  // namespace sim::world

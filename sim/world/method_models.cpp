#include "sim/world/method_models.h"

#include <stdexcept>

namespace sim::world {

const MethodModel& methodModel(CollisionMethod method) {
  for (const MethodModel& m : kMethodModels)
    if (m.method == method) return m;
  throw std::logic_error("methodModel: 'auto' has no row of its own; resolve it first");
}

std::string phenomenaText(unsigned bits) {
  static constexpr std::pair<Phenomenon, const char*> kNames[] = {
      {Phenomenon::IsolatedImpacts, "isolated impacts"},
      {Phenomenon::FrictionAtImpacts, "friction at impacts"},
      {Phenomenon::SlidingFriction, "sliding friction"},
      {Phenomenon::RestingContact, "resting contact"},
      {Phenomenon::Stacks, "stacks"},
  };
  std::string s;
  for (const auto& [p, name] : kNames)
    if (has(bits, p)) s += (s.empty() ? "" : ", ") + std::string(name);
  return s.empty() ? "nothing" : s;
}

CollisionMethod leastMethodFor(unsigned needs) {
  for (CollisionMethod m : {CollisionMethod::None, CollisionMethod::Event, CollisionMethod::Sequential})
    if ((methodModel(m).models & needs) == needs) return m;
  return CollisionMethod::Sequential;
}

}  // namespace sim::world

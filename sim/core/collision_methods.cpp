#include "sim/core/collision_methods.h"

#include <utility>

namespace sim::core {

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

const MethodModel* findMethod(std::span<const MethodModel> table, CollisionMethod method) {
  for (const MethodModel& m : table)
    if (m.method == method) return &m;
  return nullptr;
}

CollisionMethod leastMethodFor(std::span<const MethodModel> table, std::span<const CollisionMethod> order, unsigned needs) {
  for (CollisionMethod m : order)
    if (const MethodModel* row = findMethod(table, m); row && (row->models & needs) == needs) return m;
  return order.back();
}

}  // namespace sim::core

#include "sim/world/contact.h"

#include <array>
#include <cmath>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

namespace {
constexpr std::array<std::pair<CollisionMethod, std::string_view>, 5> kNames{{
    {CollisionMethod::Auto, "auto"},
    {CollisionMethod::None, "none"},
    {CollisionMethod::Event, "event"},
    {CollisionMethod::Isolated, "isolated"},
    {CollisionMethod::Sequential, "sequential"},
}};
}  // namespace

std::string_view collisionMethodName(CollisionMethod method) {
  for (const auto& [m, name] : kNames)
    if (m == method) return name;
  return "?";
}

std::optional<CollisionMethod> collisionMethodFromName(std::string_view name) {
  for (const auto& [m, n] : kNames)
    if (n == name) return m;
  return std::nullopt;
}

const std::vector<std::string_view>& collisionMethodNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> v;
    for (const auto& entry : kNames) v.push_back(entry.second);
    return v;
  }();
  return names;
}

double combinedRestitution(double a, double b) { return std::max(a, b); }
double combinedFriction(double a, double b) { return std::sqrt(a * b); }

}  // namespace sim::world

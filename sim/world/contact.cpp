#include "sim/world/contact.h"

#include <array>
#include <cmath>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

namespace {
constexpr std::array<std::pair<CollisionMethod, std::string_view>, 6> kNames{{
    {CollisionMethod::Auto, "auto"},
    {CollisionMethod::None, "none"},
    {CollisionMethod::Event, "event"},
    {CollisionMethod::Isolated, "isolated"},
    {CollisionMethod::Sequential, "sequential"},
    {CollisionMethod::SoftStep, "soft_step"},
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

void matchWarmStart(const std::vector<Contact>& contacts, std::vector<Contact>& fresh) {
  size_t old = 0;
  for (Contact& c : fresh) {
    while (old < contacts.size() && std::make_pair(contacts[old].a, contacts[old].b) < std::make_pair(c.a, c.b)) ++old;
    if (old == contacts.size() || contacts[old].a != c.a || contacts[old].b != c.b) continue;
    const Contact& prev = contacts[old];
    for (int k = 0; k < c.manifold.count; ++k)
      for (int m = 0; m < prev.manifold.count; ++m)
        if (prev.manifold.points[m].id == c.manifold.points[k].id) {
          c.state[k].normalImpulse = prev.state[m].normalImpulse;
          c.state[k].tangentImpulse = prev.state[m].tangentImpulse;
        }
  }
}

}  // namespace sim::world

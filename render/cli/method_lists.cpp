#include "render/cli/method_lists.h"

#include <sstream>

#include "render/cli/commands.h"

namespace render::cli {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

namespace {

template <class Lookup>
auto namedList(const std::string& text, Lookup lookup, const std::vector<std::string_view>& names, const std::string& option) {
  std::vector<typename decltype(lookup(""))::value_type> out;
  for (const std::string& item : splitList(text)) {
    const auto value = lookup(item);
    if (!value) {
      std::string known;
      for (auto n : names) known += (known.empty() ? "" : ", ") + std::string(n);
      throw UsageError(option + ": unknown name '" + item + "'; choose from: " + known);
    }
    out.push_back(*value);
  }
  if (out.empty()) throw UsageError(option + ": give at least one name");
  return out;
}

}  // namespace

void MethodLists::addTo(CLI::App& command) {
  command.add_option("--integrators", integrators, "comma-separated integrators (default: all four)");
  command.add_option("--collisions", collisions, "comma-separated collision methods (default: the scene's)");
}

std::vector<sim::core::Integrator> MethodLists::integratorList() const {
  if (integrators.empty())
    return {sim::core::Integrator::ExplicitEuler, sim::core::Integrator::SymplecticEuler, sim::core::Integrator::Midpoint, sim::core::Integrator::Rk4};
  return namedList(integrators, sim::core::integratorFromName, sim::core::integratorNames(), "--integrators");
}

std::vector<sim::world::CollisionMethod> MethodLists::collisionList(const std::vector<sim::world::CollisionMethod>& defaults) const {
  if (collisions.empty()) return defaults;
  return namedList(collisions, sim::world::collisionMethodFromName, sim::world::collisionMethodNames(), "--collisions");
}

}  // namespace render::cli

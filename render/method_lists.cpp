#include "method_lists.h"

#include <sstream>

#include "commands.h"

namespace render {

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

std::vector<sim::Integrator> MethodLists::integratorList() const {
  if (integrators.empty())
    return {sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler, sim::Integrator::Midpoint, sim::Integrator::Rk4};
  return namedList(integrators, sim::integratorFromName, sim::integratorNames(), "--integrators");
}

std::vector<sim::CollisionMethod> MethodLists::collisionList(sim::CollisionMethod scenes) const {
  if (collisions.empty()) return {scenes};
  return namedList(collisions, sim::collisionMethodFromName, sim::collisionMethodNames(), "--collisions");
}

}  // namespace render

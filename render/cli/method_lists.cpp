#include "render/cli/method_lists.h"

#include <sstream>

#include "render/cli/commands.h"

namespace render::cli {
using namespace render::jobs;

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

namespace {

template <class Lookup>
auto namedList(const std::string& text, Lookup lookup, const std::string& known, const std::string& option) {
  std::vector<typename decltype(lookup(""))::value_type> out;
  for (const std::string& item : splitList(text)) {
    const auto value = lookup(item);
    if (!value) throw UsageError(option + ": unknown name '" + item + "'; choose from: " + known);
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
  if (integrators.empty()) {
    std::vector<sim::core::Integrator> all;
    for (const auto& entry : sim::core::kIntegratorNames.entries()) all.push_back(entry.value);
    return all;
  }
  return namedList(integrators, sim::core::integratorFromName, sim::core::kIntegratorNames.list(), "--integrators");
}

std::vector<sim::core::CollisionMethod> MethodLists::collisionList(
    const std::vector<sim::core::CollisionMethod>& defaults) const {
  if (collisions.empty()) return defaults;
  return namedList(collisions, sim::core::collisionMethodFromName, sim::core::kCollisionMethodNames.list(), "--collisions");
}

}  // namespace render::cli

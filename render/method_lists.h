// The --integrators and --collisions lists that sweep and stability take.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "contact.h"
#include "integrators.h"

namespace render {

// "a,b,c" → {"a", "b", "c"}, empty items dropped
std::vector<std::string> splitList(const std::string& text);

struct MethodLists {
  std::string integrators, collisions;

  void addTo(CLI::App& command);
  // the named integrators, or all four; throws UsageError naming the unknown one
  std::vector<sim::Integrator> integratorList() const;
  // the named collision methods, or the scene's own
  std::vector<sim::CollisionMethod> collisionList(sim::CollisionMethod scenes) const;
};

}  // namespace render

// The --integrators and --collisions lists that sweep and stability take.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "sim/core/integrators.h"
#include "sim/world/contact.h"

namespace render::cli {

// "a,b,c" → {"a", "b", "c"}, empty items dropped
std::vector<std::string> splitList(const std::string& text);

struct MethodLists {
  std::string integrators, collisions;

  void addTo(CLI::App& command);
  // the named integrators, or all four; throws UsageError naming the unknown one
  std::vector<sim::core::Integrator> integratorList() const;
  // the named collision methods, or the scene's own
  std::vector<sim::world::CollisionMethod> collisionList(sim::world::CollisionMethod scenes) const;
};

}  // namespace render::cli

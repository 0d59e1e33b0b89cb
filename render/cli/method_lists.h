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
  // the named collision methods, or `defaults` (the scene's own, or those its variants choose)
  std::vector<sim::core::CollisionMethod> collisionList(const std::vector<sim::core::CollisionMethod>& defaults) const;
};

}  // namespace render::cli

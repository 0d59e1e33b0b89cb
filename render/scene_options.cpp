#include "scene_options.h"

#include <cmath>

#include "commands.h"
#include "scene_yaml.h"

namespace render {

void SceneOptions::addTo(CLI::App& command) {
  command.add_option("--variant", variant, "the named variant of the scene to run");
  command.add_option("--integrator", integrator, "explicit_euler, symplectic_euler, midpoint or rk4");
  command.add_option("--dt", dt, "fixed time step in seconds");
}

sim::SceneDef SceneOptions::load() const {
  sim::SceneDef def = sim::loadSceneFile(scene, variant);
  if (!integrator.empty()) {
    const auto method = sim::integratorFromName(integrator);
    if (!method) {
      std::string names;
      for (auto n : sim::integratorNames()) names += (names.empty() ? "" : ", ") + std::string(n);
      throw UsageError("--integrator: unknown integrator '" + integrator + "'; choose one of: " + names);
    }
    def.integrator = *method;
  }
  if (dt) {
    if (!(*dt > 0.0) || !std::isfinite(*dt)) throw UsageError("--dt: the time step must be a positive finite number");
    def.dt = *dt;
  }
  return def;
}

}  // namespace render

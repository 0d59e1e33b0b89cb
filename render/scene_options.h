// Command-line overrides of a scene's `sim:` settings, shared by the subcommands that run scenes.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "scene_def.h"

namespace render {

struct SceneOptions {
  std::string scene;
  std::string variant;
  std::string integrator;
  std::optional<double> dt;

  // --variant, --integrator, --dt
  void addTo(CLI::App& command);
  // the scene with the overrides applied; throws sim::SceneError or UsageError
  sim::SceneDef load() const;
};

}  // namespace render

// Command-line overrides of a scene's `sim:` settings, shared by the subcommands that run scenes.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "scene_def.h"
#include "world.h"

namespace render {

struct SceneOptions {
  std::string scene;
  std::string variant;
  std::string integrator;
  std::optional<double> dt;
  std::string collisions;

  // --variant, --integrator, --dt, --collisions
  void addTo(CLI::App& command);
  // the scene with the overrides applied; throws sim::SceneError or UsageError
  sim::SceneDef load() const;
};

// the scene's world, started: `auto` resolved and the start state checked; bodies that overlap
// where the method cannot start become a sim::SceneError at the second body's line
sim::World startWorld(const sim::SceneDef& def, const std::string& file);

// "event: no bodies touch at the start, so impacts are isolated"
std::string describeCollisionMethod(const sim::World& world);

}  // namespace render

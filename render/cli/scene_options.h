// Command-line overrides of a scene's `sim:` settings, shared by the subcommands that run scenes.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "render/cli/energy_report.h"
#include "render/cli/scene_file.h"
#include "render/video/render_plan.h"
#include "sim/scene/scene_def.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::cli {

struct SceneOptions {
  std::string scene;
  std::string variant;
  std::string integrator;
  std::optional<double> dt;
  std::string collisions;
  std::optional<int> substeps;         // soft_step's sim: substeps
  std::optional<double> contactHertz;  // soft_step's sim: contact_hertz, Hz
  std::optional<int> threads;          // soft_step's sim: threads
  std::string precision;               // soft_step's sim: precision

  // --variant, --integrator, --dt, --collisions, --substeps, --contact-hertz, --threads, --precision
  void addTo(CLI::App& command);
  // the scene file, read and parsed on first use and once: is3d() says which path to take
  const OpenScene& open() const;
  bool is3d() const { return open().is3d(); }
  // the scene with the overrides applied; throws sim::yaml::SceneError or UsageError
  SceneFile load() const;
  // the same for a 3D scene (dimensions: 3), whose integrators include the splitting and which has
  // no collision method to choose (nor soft_step's settings)
  SceneFile3d load3d() const;
  // any variant of the scene ("" the base scene) with the overrides applied, as a render plan reads them
  render::video::LoadVariant variantLoader() const;
  // the same for a 3D scene's variants
  render::video::LoadVariant3d variantLoader3d() const;

 private:
  mutable std::shared_ptr<const OpenScene> opened_;  // (shared by copies, as the variant loaders make)
};

// on standard error, once per run, what the scene's named collision method leaves out of what it
// asks for, at the key that named it: "FILE:LINE:COL: warning: 'collisions: event': ..."
// (sim/scene/model_warnings.h)
void warnOfModel(const sim::scene::SceneDef& def, const std::string& file);

// the scene's world, started: `auto` resolved and the start state checked; bodies that overlap
// where the method cannot start become a sim::yaml::SceneError at the second body's line
sim::world::World startWorld(const sim::scene::SceneDef& def, const std::string& file);

// "event: no bodies touch at the start, so impacts are isolated"
std::string describeCollisionMethod(const sim::scene::SceneDef& def, const sim::world::World& world);
std::string describeCollisionMethod(const sim::scene3d::SceneDef& def, const sim::world3d::World& world);
// when `auto` went from event to the resting-contact solver during the run, and why: "event until
// t = 0.604 s, then sequential: 'floor' and 'box' stayed in contact (...)"; empty when it did not
std::string describeMethodSwitch(const sim::scene::SceneDef& def, const sim::world::World& world);
std::string describeMethodSwitch(const sim::scene3d::SceneDef& def, const sim::world3d::World& world);
// a body's name by its index; in 3D a plane's by −1 − its index (as contacts and impacts name it)
NameOf namesOf(const sim::scene::SceneDef& def);
NameOf namesOf(const sim::scene3d::SceneDef& def);

// where the event method turned a pile-up of impacts into resting contact: "'ball' and 'floor' came
// to rest at t = 2.4 (...)", or, when the pair keeps sliding or turning while it touches, "'bar' and
// 'floor' stay in contact from t = 0.5 (...)"
std::string describeResting(const sim::scene::SceneDef& def, const sim::world::RestingRecord& record);

// one impulse the collision response applied, for -v: "t = 0.5: 'ball' and 'floor' at (0, -1),
// normal (0, 1), j = 2, tangent j = 0, v_n -2 -> 1.4"
std::string describeImpact(const sim::scene::SceneDef& def, const sim::world::ImpactRecord& record);

// the records of one pair and kind (resting or still moving) merged: a pentagon rocking on a slab
// makes a record at every pile-up, a hundred near-identical lines
struct RestingSpan {
  sim::world::RestingRecord first;
  double last = 0.0;  // s, the time of the last record
  long count = 0;
};
// one span per pair and kind, in the order of their first records
std::vector<RestingSpan> mergeResting(const std::vector<sim::world::RestingRecord>& records);
// "'bar' and 'floor' stay in contact from t = 0.5 to 2.9 (139 times; ...)", or as one record
std::string describeResting(const sim::scene::SceneDef& def, const RestingSpan& span);

}  // namespace render::cli

// The scene file's `stability:` block: what `rigidreel stability` searches (documented in
// scenes/README.md), read by the analysis from the same YAML tree as the model.
#pragma once

#include <string>

#include "sim/core/enum_names.h"
#include "sim/scene/scene_def.h"

namespace sim::yaml {
struct SceneSource;
}

namespace render::analysis {

// the scene's top-level key this block is read from
inline constexpr const char* kStabilityKey = "stability";

// the parameter the search grows for the largest value at which the scene still holds; for the
// solver's effort (sequential's iterations, soft_step's substeps) the fewest at which it holds
struct StabilityDef {
  enum class Parameter { Dt, Speed, MassRatio, StackHeight, PyramidBase, Iterations, Substeps };
  Parameter parameter = Parameter::Dt;
  std::string body;    // speed: whose speed; mass_ratio: whose mass and inertia are scaled
  double from = 0.0;   // where the search starts (0: from the scene's own value)
  double to = 0.0;     // the largest value tried (0: no limit but the search's own)
  bool stack = false;  // the stack criterion applies: the top box must not drift
  // when positive: every body must end within this of its start, m, and at rest; this replaces the
  // penetration criterion (a stack's contacts may sink as long as its bodies stay within it)
  double within = 0.0;
  // the search looks for the fewest iterations or substeps that hold, not the largest value
  bool fewest() const { return parameter == Parameter::Iterations || parameter == Parameter::Substeps; }
  // the parameter counts bodies: whole numbers, and the stack criterion by default
  bool countsBodies() const { return parameter == Parameter::StackHeight || parameter == Parameter::PyramidBase; }
};

// a scene as `rigidreel stability` reads it: the model and its stability: block
struct Study {
  sim::scene::SceneDef model;
  StabilityDef stability;
};

// the parameters as scenes name them
inline constexpr sim::core::EnumNames<StabilityDef::Parameter, 7> kParameterNames{{{
    {StabilityDef::Parameter::Dt, "dt"},
    {StabilityDef::Parameter::Speed, "speed"},
    {StabilityDef::Parameter::MassRatio, "mass_ratio"},
    {StabilityDef::Parameter::StackHeight, "stack_height"},
    {StabilityDef::Parameter::PyramidBase, "pyramid_base"},
    {StabilityDef::Parameter::Iterations, "iterations"},
    {StabilityDef::Parameter::Substeps, "substeps"},
}}};

// the block of `source` (the default when absent); its body names refer to `model`'s bodies.
// Throws sim::yaml::SceneError at the fault's FILE:LINE:COL.
StabilityDef readStability(const sim::yaml::SceneSource& source, const sim::scene::SceneDef& model);

}  // namespace render::analysis

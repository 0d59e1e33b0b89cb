// A scene's model as plain definitions, free of any file format and of any picture: what the YAML
// loader produces and buildWorld consumes (MuJoCo's split of the model from the simulation state,
// and of the model from its visual scene: how to draw it is the renderer's own definition).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/core/expect_def_of.h"
#include "sim/core/force_defs.h"
#include "sim/core/integrators.h"
#include "sim/core/scene_def_of.h"
#include "sim/core/settings.h"
#include "sim/core/shape.h"
#include "sim/world/contact.h"

namespace sim::scene {
namespace settings = sim::core::settings;

struct BodyDef {
  std::string name;
  sim::core::Shape shape;         // as written: body coordinates before the centroid shift
  std::optional<double> density;  // kg/m²
  // a compound shape's part densities, kg/m², one per part (none: the body's density)
  std::vector<std::optional<double>> partDensities;
  // where the center of mass is in the body's own frame, when the scene says (else the centroid)
  std::optional<sim::core::Vec2> centerOfMass;
  std::optional<double> mass;     // kg
  std::optional<double> inertia;  // kg·m², about the center of mass
  // of the center of mass; of the body's own frame for a body of parts or with centerOfMass
  sim::core::Vec2 position = sim::core::Vec2::Zero();
  double angle = 0.0;
  sim::core::Vec2 velocity = sim::core::Vec2::Zero();
  double angularVelocity = 0.0;
  bool isStatic = false;
  std::optional<double> restitution;  // c_r; the world's when absent
  std::optional<double> friction;     // μ; the world's when absent
  sim::core::SourceLoc loc;
};

using PointForceDef = sim::core::PointForceDefOf<sim::core::Vec2>;
using SpringDef = sim::core::SpringDefOf<sim::core::Vec2>;
using EventDef = sim::core::EventDefOf<sim::core::Vec2>;

// a closed-form answer that `rigidreel check` compares against (what 3D's has too: sim/core/expect_def_of.h)
struct ExpectDef : sim::core::ExpectDefOf<sim::core::Vec2> {
  std::optional<double> angle;
  std::optional<double> angularVelocity;
  std::optional<double> angularMomentum;  // world, about the origin
};

// a 2D scene's model: what 3D's has too (sim/core/scene_def_of.h), and 2D's integrator and solvers' keys
struct SceneDef : sim::core::SceneDefOf<sim::core::Vec2, BodyDef, ExpectDef> {
  sim::core::Integrator integrator = sim::core::Integrator::SymplecticEuler;
  // where `sim: {integrator}` is written (line 0: not in the file), beside collisionsLoc, for the
  // warnings of what a named method leaves out (model_warnings.h)
  sim::core::SourceLoc integratorLoc;
  int substeps = settings::kSubsteps;             // soft_step
  double contactHertz = settings::kContactHertz;  // soft_step's contact stiffness, Hz
  bool sleep = false;                             // sequential and soft_step: islands at rest fall asleep (sim/world/sleep.h)
  int threads = 1;  // soft_step: threads sharing each set of contacts (sim: threads; the same state with any)
  sim::world::Precision precision =
      sim::world::Precision::Double;  // soft_step: the numbers of its contact solve (sim: precision)
  double recycleDistance = 0.0;       // soft_step: contact recycling's distance, m (sim: recycle); 0: off
};

}  // namespace sim::scene

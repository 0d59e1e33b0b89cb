// A scene's model as plain definitions, free of any file format and of any picture: what the YAML
// loader produces and buildWorld consumes (MuJoCo's split of the model from the simulation state,
// and of the model from its visual scene: how to draw it is the renderer's own definition).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/core/force_defs.h"
#include "sim/core/integrators.h"
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

// a closed-form answer that `rigidreel check` compares against; absent fields are not checked
struct ExpectDef {
  double time = 0.0;
  std::string body;  // empty for world-wide quantities
  std::optional<sim::core::Vec2> position;
  std::optional<double> angle;
  std::optional<sim::core::Vec2> velocity;
  std::optional<double> angularVelocity;
  std::optional<double> kineticEnergy;      // of `body`, or of the world when no body is named
  std::optional<double> potentialEnergy;    // world
  std::optional<double> totalEnergy;        // world
  std::optional<sim::core::Vec2> momentum;  // world
  std::optional<double> angularMomentum;    // world, about the origin
  // the energy, less the work of applied forces and impulse events, never rises by more than the
  // tolerance above its lowest value so far, at any step up to `time` (sim/world/energy_ledger.h)
  bool energyNeverRises = false;
  double tolerance = settings::kDefaultExpectTolerance;
  bool earlierRun = false;  // source: earlier_run, a value an earlier run gave (else a closed form)
  sim::core::SourceLoc loc;
};

struct SceneDef {
  std::string name;
  std::string description;
  std::string variant;  // the variant merged in, empty for the base scene
  std::vector<std::string> variantNames;
  double duration = settings::kDefaultDuration;
  sim::core::Vec2 gravity = sim::core::Vec2::Zero();
  double restitution = settings::kDefaultRestitution;
  // μ of every body that names none; unset, the default (0) is not a μ the scene named, and a pair
  // with a body that names one takes that body's (sim::world::combinedFriction)
  std::optional<double> friction;
  sim::core::Integrator integrator = sim::core::Integrator::SymplecticEuler;
  double dt = settings::kDefaultDt;
  double maxSteps = settings::kDefaultMaxSteps;  // the most steps a run may take (sim: max_steps)
  sim::core::SourceLoc stepsLoc;                 // where dt (or else duration) is set, for messages
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;
  // where `sim: {collisions}` and `sim: {integrator}` are written (line 0: not in the file, e.g. set
  // on the command line), for the warnings of what a named method leaves out (model_warnings.h)
  sim::core::SourceLoc collisionsLoc, integratorLoc;
  int velocityIterations = settings::kVelocityIterations;
  int positionIterations = settings::kPositionIterations;
  int substeps = settings::kSubsteps;             // soft_step
  double contactHertz = settings::kContactHertz;  // soft_step's contact stiffness, Hz
  bool sleep = false;                             // sequential and soft_step: islands at rest fall asleep (sim/world/sleep.h)
  int threads = 1;  // soft_step: threads sharing each set of contacts (sim: threads; the same state with any)
  sim::world::Precision precision =
      sim::world::Precision::Double;  // soft_step: the numbers of its contact solve (sim: precision)
  double recycleDistance = 0.0;       // soft_step: contact recycling's distance, m (sim: recycle); 0: off
  std::vector<BodyDef> bodies;
  std::vector<PointForceDef> pointForces;
  std::vector<SpringDef> springs;
  std::vector<sim::core::DragDef> drags;
  std::vector<EventDef> events;
  std::vector<ExpectDef> expects;

  // index of the body with this name, or -1 (a scan: for one lookup)
  int bodyIndex(const std::string& name) const;
  // every body's index by its name: for lookups of many entries, in one pass
  std::unordered_map<std::string, int> bodyIndices() const;
};

}  // namespace sim::scene

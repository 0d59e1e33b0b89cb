// A 3D scene's model (`dimensions: 3`) as plain definitions, free of any file format and of any
// picture: what the 3D reader produces and buildWorld consumes, as sim/scene's SceneDef is for 2D.
// Contacts in 3D are with static planes and between spheres (sim/world3d/methods3d.h).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/core/collision_methods.h"
#include "sim/core/force_defs.h"
#include "sim/core/settings.h"
#include "sim/world3d/integrators.h"
#include "sim/world3d/shape.h"

namespace sim::scene3d {

struct BodyDef {
  std::string name;
  sim::world3d::Shape shape;                                        // body coordinates, centered on the center of mass
  std::optional<double> density;                                    // kg/m³
  std::optional<double> mass;                                       // kg
  std::optional<sim::world3d::Mat3> inertia;                        // kg·m² about the center, body axes
  sim::world3d::Vec3 position = sim::world3d::Vec3::Zero();         // of the center of mass, world
  sim::world3d::Quat orientation = sim::world3d::Quat::Identity();  // body to world, unit
  sim::world3d::Vec3 velocity = sim::world3d::Vec3::Zero();         // world
  sim::world3d::Vec3 angularVelocity = sim::world3d::Vec3::Zero();  // world
  std::optional<double> restitution;                                // c_r; the world's when absent
  std::optional<double> friction;  // μ; the world's when absent (2D's rule: sim/scene/scene_def.h)
  sim::core::SourceLoc loc;
  sim::core::SourceLoc massLoc;  // where the mass properties are written (the body when they are not)
};

// a static half-space, written in `bodies:` as {plane: {point, normal}}: solid behind its normal
struct PlaneDef {
  std::string name;
  sim::world3d::Vec3 point = sim::world3d::Vec3::Zero();
  sim::world3d::Vec3 normal = sim::world3d::Vec3::UnitZ();  // unit, as read
  std::optional<double> restitution, friction;
  sim::core::SourceLoc loc;
};

using PointForceDef = sim::core::PointForceDefOf<sim::world3d::Vec3>;
using SpringDef = sim::core::SpringDefOf<sim::world3d::Vec3>;
using EventDef = sim::core::EventDefOf<sim::world3d::Vec3>;

// a closed-form answer that `rigidreel check` compares against; absent fields are not checked
struct ExpectDef {
  double time = 0.0;
  std::string body;  // empty for world-wide quantities
  // a body's state at `time`
  std::optional<sim::world3d::Vec3> position, velocity, angularVelocity;
  std::optional<sim::world3d::Quat> orientation;  // q and −q are the same rotation: compared with the nearer
  std::optional<double> quaternionNorm;           // |q|, which drifts without normalization
  // energies (kinetic: the body's, or the world's without a body) and momenta (angular: the body's
  // about its center, or the world's about the origin without a body)
  std::optional<double> kineticEnergy, potentialEnergy, totalEnergy;
  std::optional<sim::world3d::Vec3> momentum, angularMomentum;
  // the energy, less the work of applied forces and events, never rises above its lowest so far by
  // more than the tolerance, at any step up to `time` (2D's: sim/scene/scene_def.h)
  bool energyNeverRises = false;
  // the free body's closed forms (closed_forms.h): the angle between ω and L at `time`, and what the
  // run from t = 0 to `time` measures (measures.h): the rates at which ω turns about the symmetry
  // axis in the body and the symmetry axis about L in space, and the period of ω's middle-axis part
  std::optional<double> coneAngle, precessionRate, spacePrecessionRate, flipPeriod;
  double tolerance = sim::core::settings::kDefaultExpectTolerance;
  bool earlierRun = false;  // source: earlier_run, a value an earlier run gave (else a closed form)
  sim::core::SourceLoc loc;
};

struct SceneDef {
  std::string name;
  std::string description;
  std::string variant;  // the variant merged in, empty for the base scene
  std::vector<std::string> variantNames;
  double duration = sim::core::settings::kDefaultDuration;
  sim::world3d::Vec3 gravity = sim::world3d::Vec3::Zero();
  sim::world3d::Integrator integrator = sim::world3d::Integrator::Splitting;
  double dt = sim::core::settings::kDefaultDt;
  double maxSteps = sim::core::settings::kDefaultMaxSteps;        // the most steps a run may take (sim: max_steps)
  bool normalize = true;                                          // q ← q/|q| after every step (World::normalizeQuaternions)
  double restitution = sim::core::settings::kDefaultRestitution;  // of every body and plane that names none
  std::optional<double> friction;                                 // unset: only what a body names
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;
  sim::core::SourceLoc collisionsLoc;
  int velocityIterations = sim::core::settings::kVelocityIterations;  // sequential
  int positionIterations = sim::core::settings::kPositionIterations;
  std::vector<BodyDef> bodies;
  std::vector<PlaneDef> planes;
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

}  // namespace sim::scene3d

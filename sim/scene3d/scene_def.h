// A 3D scene's model (`dimensions: 3`) as plain definitions, free of any file format and of any
// picture: what the 3D reader produces and buildWorld consumes, as sim/scene's SceneDef is for 2D.
// Contacts in 3D are with static planes and between spheres (sim/world3d/methods3d.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/core/expect_def_of.h"
#include "sim/core/force_defs.h"
#include "sim/core/scene_def_of.h"
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

// a closed-form answer that `rigidreel check` compares against (what 2D's has too: sim/core/expect_def_of.h)
struct ExpectDef : sim::core::ExpectDefOf<sim::world3d::Vec3> {
  // the body's rotation at `time`
  std::optional<sim::world3d::Vec3> angularVelocity;
  std::optional<sim::world3d::Quat> orientation;  // q and −q are the same rotation: compared with the nearer
  std::optional<double> quaternionNorm;           // |q|, which drifts without normalization
  // the body's about its center, or the world's about the origin without a body
  std::optional<sim::world3d::Vec3> angularMomentum;
  // the free body's closed forms (closed_forms.h): the angle between ω and L at `time`, and what the
  // run from t = 0 to `time` measures (measures.h): the rates at which ω turns about the symmetry
  // axis in the body and the symmetry axis about L in space, and the period of ω's middle-axis part
  std::optional<double> coneAngle, precessionRate, spacePrecessionRate, flipPeriod;
};

// a 3D scene's model: what 2D's has too (sim/core/scene_def_of.h), and 3D's integrator and planes
struct SceneDef : sim::core::SceneDefOf<sim::world3d::Vec3, BodyDef, ExpectDef> {
  sim::world3d::Integrator integrator = sim::world3d::Integrator::Splitting;
  bool normalize = true;  // q ← q/|q| after every step (WorldDef::normalizeQuaternions)
  std::vector<PlaneDef> planes;
};

}  // namespace sim::scene3d

// Forces on 3D bodies, each applied at a point and so giving the torque τ = r′ × f about the
// center (notes: "Forces and torques"), and the potential energy of the conservative ones.
#pragma once

#include <limits>
#include <vector>

#include "sim/core/forces.h"
#include "sim/world3d/body.h"

namespace sim::world3d {

// a constant force at a body point, on during [from, until)
struct PointForce {
  int body = 0;
  Vec3 point = Vec3::Zero();  // body coordinates
  Vec3 force = Vec3::Zero();  // world coordinates, or body coordinates when bodyFrame
  bool bodyFrame = false;     // the force turns with the body
  double from = 0.0;
  double until = std::numeric_limits<double>::infinity();
};

// a damped linear spring between a body point and a world anchor or another body's point
struct Spring {
  int bodyA = 0;
  Vec3 pointA = Vec3::Zero();           // body coordinates of A
  int bodyB = sim::core::kWorldAnchor;  // or a spring end fixed in the world
  Vec3 pointB = Vec3::Zero();           // body coordinates of B, or the world anchor
  double stiffness = 0.0;               // N/m
  double restLength = 0.0;              // m
  double damping = 0.0;                 // N·s/m, along the spring
};

// linear and angular drag: f = −c v, τ = −c_ω ω (ω in the world frame)
struct Drag {
  int body = 0;
  double linear = 0.0;   // N·s/m
  double angular = 0.0;  // N·m·s
};

// the net force and the torque about the center of mass on one body, world frame
struct Wrench {
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
};
using Wrenches = std::vector<Wrench>;

struct ForceSet {
  Vec3 gravity = Vec3::Zero();  // m/s², acting at every center of mass
  std::vector<PointForce> pointForces;
  std::vector<Spring> springs;
  std::vector<Drag> drags;

  // the wrench on each body at the states `at` (poses and velocities may differ from the bodies'
  // own, e.g. an integrator's stage); `window` is a time inside the current step, which decides
  // which timed forces are on
  void accumulate(double window, const std::vector<Body>& bodies, const std::vector<BodyState>& at, Wrenches& out) const;

  // gravity's −m g·x and the springs' ½ k (|d| − l₀)², at the bodies' own states, J
  double potentialEnergy(const std::vector<Body>& bodies) const;

  // times at which a force switches on or off: the step is split there
  std::vector<double> breakpoints() const;

  // whether some force depends on the velocities (drag, spring damping): the splitting then
  // takes two force evaluations per kick instead of one
  bool dependsOnVelocity() const;

  // for the energy ledger (sim/core/energy_ledger_of.h), as the 2D ForceSet's: some force does work
  // that no potential counts; the point forces' work over a step (f · Δr of their points); the
  // damping's power (≤ 0) at `at`
  bool hasWorkingForces() const { return !pointForces.empty() || dependsOnVelocity(); }
  double pointForceWork(double window, const std::vector<BodyState>& from, const std::vector<BodyState>& to) const;
  sim::core::ForcePower power(double window, const std::vector<BodyState>& at) const;
};

}  // namespace sim::world3d

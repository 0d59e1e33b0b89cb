// Forces on 3D bodies, each applied at a point and so giving the torque τ = r′ × f about the
// center (notes: "Forces and torques"), and the potential energy of the conservative ones.
#pragma once

#include <vector>

#include "sim/core/force_set_of.h"
#include "sim/core/forces.h"
#include "sim/world3d/body.h"

namespace sim::world3d {

using PointForce = sim::core::PointForceOf<Vec3>;
using Spring = sim::core::SpringOf<Vec3>;

// the net force and the torque about the center of mass on one body, world frame
struct Wrench {
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
};
using Wrenches = std::vector<Wrench>;

// the 3D world's forces (what they are: sim/core/force_set_of.h), and what they do to its bodies
struct ForceSet : sim::core::ForceSetOf<Vec3> {
  // the wrench on each body at the states `at` (poses and velocities may differ from the bodies'
  // own, e.g. an integrator's stage); `window` is a time inside the current step, which decides
  // which timed forces are on
  void accumulate(double window, const std::vector<Body>& bodies, const std::vector<BodyState>& at, Wrenches& out) const;

  // gravity's −m g·x and the springs' ½ k (|d| − l₀)², at the bodies' own states, J
  double potentialEnergy(const std::vector<Body>& bodies) const;

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

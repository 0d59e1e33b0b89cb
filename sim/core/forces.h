// Forces applied at points, each giving a torque τ = r′ × f (notes: "Forces and torques").
#pragma once

#include <vector>

#include "sim/core/body.h"
#include "sim/core/force_set_of.h"

namespace sim::core {

using PointForce = PointForceOf<Vec2>;
using Spring = SpringOf<Vec2>;

// the rate at which the forces that have no potential do work on the bodies, W/s: the applied point
// forces (what a scene puts in) and the damping of drags and springs (what it takes out, ≤ 0);
// gravity and the springs' stretch are in the potential energy instead
struct ForcePower {
  double applied = 0.0;
  double damping = 0.0;
};

// the 2D world's forces (what they are: force_set_of.h), and what they do to its bodies
struct ForceSet : ForceSetOf<Vec2> {
  // net force and torque about the center of mass of each body, for the given states;
  // `window` is a time inside the current step, which decides which timed forces are on
  void accumulate(double window, const std::vector<Body>& bodies, const std::vector<BodyState>& states, std::vector<Vec2>& force,
                  std::vector<double>& torque) const;

  // gravity and spring potential energy (constant and drag forces have none)
  double potentialEnergy(const std::vector<Body>& bodies) const;

  // f · (v + ω × r′) summed over the forces without a potential, at `states` (`window` as accumulate's)
  ForcePower power(double window, const std::vector<BodyState>& states) const;
  // the work of the point forces on during a step from `from` to `to` (`window` inside it): f · Δr of
  // each force's point, exact for a force fixed in the world whatever path the point took; a force
  // that turns with its body takes the mean of its two directions (second order in the step)
  double pointForceWork(double window, const std::vector<BodyState>& from, const std::vector<BodyState>& to) const;
  // some force does work that no potential counts (a point force, a drag, a damped spring)
  bool hasWorkingForces() const;

  // only gravity acts (or nothing): every body falls on a parabola of its own, exactly
  bool gravityOnly() const { return pointForces.empty() && springs.empty() && drags.empty(); }
};

}  // namespace sim::core

// Shared 3D scenes and measures for tests/sim/world3d: the 3D layer has no scene files yet, so its
// scenes are built here in code, once.
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/world3d/diagnostics.h"
#include "sim/world3d/world.h"

namespace fixtures3d {
using sim::core::kWorldAnchor;
using sim::world3d::angularMomentum;
using sim::world3d::axisAngle;
using sim::world3d::Body;
using sim::world3d::energy;
using sim::world3d::Integrator;
using sim::world3d::makeBody;
using sim::world3d::makeBox;
using sim::world3d::makeEllipsoid;
using sim::world3d::Spring;
using sim::world3d::StepObserver;
using sim::world3d::Vec3;
using sim::world3d::World;

// a free box of sides 0.2 × 0.4 × 0.6 m (three distinct moments), 1 kg, tilted and spun about an
// axis off all three principal axes; no forces: L and E are constant, ω wanders
inline World freeBox(Integrator method, double dt, const Vec3& omega = Vec3(1.0, 2.0, 3.0)) {
  Body box = makeBody(makeBox(Vec3(0.2, 0.4, 0.6)), 1.0 / 0.048);
  box.q = axisAngle(Vec3(1, 1, 0), 0.4);
  box.v = Vec3(0.1, 0, 0);
  box.omega = omega;
  sim::world3d::WorldDef def;
  def.integrator = method;
  def.dt = dt;
  return World(def, {box});
}

// translation and rotation coupled: a box hung from a world anchor by a spring at a corner, under
// gravity, tilted and spinning, with a lightly damped spring to an ellipsoid below it and angular
// drag on the ellipsoid (so the velocity-dependent forces are exercised too)
inline World springChain(Integrator method, double dt) {
  Body box = makeBody(makeBox(Vec3(0.2, 0.4, 0.6)), 20.0);
  box.x = Vec3(0.2, -0.1, -1.0);
  box.q = axisAngle(Vec3(1, 2, 0), 0.5);
  box.omega = Vec3(0.5, -1.0, 2.0);
  Body ellipsoid = makeBody(makeEllipsoid(Vec3(0.1, 0.15, 0.25)), 40.0);
  ellipsoid.x = Vec3(0.0, 0.2, -2.0);
  ellipsoid.omega = Vec3(0.0, 3.0, 1.0);
  sim::world3d::WorldDef def;
  def.forces.gravity = Vec3(0, 0, -9.81);
  def.forces.springs.push_back({0, Vec3(0.1, 0.2, 0.3), kWorldAnchor, Vec3(0, 0, 0), 60.0, 0.5, 0.0});
  def.forces.springs.push_back({0, Vec3(-0.1, 0.2, -0.3), 1, Vec3(0, 0, 0.25), 40.0, 0.5, 0.2});
  def.forces.drags.push_back({1, 0.0, 0.01});
  def.integrator = method;
  def.dt = dt;
  return World(def, {box, ellipsoid});
}

// a distance in state space, summed over the bodies: |Δx| + |Δq| + |Δv| + |Δω| (m, 1, m/s, rad/s:
// the scenes are of unit size)
inline double stateDistance(const World& a, const World& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.bodies.size(); ++i) {
    const Body &p = a.bodies[i], &q = b.bodies[i];
    d += (p.x - q.x).norm() + (p.q.coeffs() - q.q.coeffs()).norm() + (p.v - q.v).norm() + (p.omega - q.omega).norm();
  }
  return d;
}

// the relative drift of L (about the origin) and of E over a run, sampled after every step
struct Drift : StepObserver {
  Vec3 momentum0;
  double energy0;
  double momentum = 0.0;            // the largest |L − L₀| / |L₀|
  std::vector<double> energyError;  // (E − E₀) / |E₀| after each step
  explicit Drift(const World& w) : momentum0(angularMomentum(w)), energy0(energy(w).total()) {}
  void afterStep(const World& w) override {
    momentum = std::max(momentum, (angularMomentum(w) - momentum0).norm() / momentum0.norm());
    energyError.push_back((energy(w).total() - energy0) / std::abs(energy0));
  }
  // the largest |E − E₀| / |E₀| over the steps [from, to)
  double largestEnergyError(size_t from, size_t to) const {
    double largest = 0.0;
    for (size_t i = from; i < to; ++i) largest = std::max(largest, std::abs(energyError[i]));
    return largest;
  }
};

inline Drift runDrift(World w, double until) {
  Drift d(w);
  w.advanceTo(until, &d);
  return d;
}

// |actual − expected| / |expected| (doctest's Approx adds 1 to the scale, which makes it an
// absolute test for small quantities)
inline double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

// the least-squares slope of log(error) against log(dt)
inline double fittedOrder(const std::vector<double>& dts, const std::vector<double>& errors) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(dts.size());
  for (size_t i = 0; i < dts.size(); ++i) {
    const double x = std::log(dts[i]), y = std::log(errors[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace fixtures3d

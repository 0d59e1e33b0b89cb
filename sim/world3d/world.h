// The 3D world: free rigid bodies (no contacts), forces and timed impulses, advanced by one
// integrator on a fixed step grid split exactly at every event and force switch, as the 2D world
// (notes: "Dynamics of a free body", "Impulses"; the 3D half of "Representing rigid body state").
#pragma once

#include <stdexcept>
#include <vector>

#include "sim/core/settings.h"
#include "sim/world3d/integrators.h"
#include "sim/core/step_grid.h"

namespace sim::world3d {

// an impulse j applied at exactly `time`: Δv = j/m, Δω = I⁻¹ (r′ × j) with I = R I_b Rᵀ
struct ImpulseEvent {
  double time = 0.0;
  int body = 0;
  Vec3 point = Vec3::Zero();  // body coordinates, or world coordinates when pointInWorld
  bool pointInWorld = false;
  Vec3 impulse = Vec3::Zero();  // world coordinates, N·s
};

class World;

// told of every finished step and every applied event, e.g. to write a trace
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void afterStep(const World&) {}
  virtual void afterEvent(const World&, const ImpulseEvent&) {}
};

// a body's state stopped being finite
struct Diverged : std::runtime_error {
  Diverged(double time, int body);
  double time;
  int body;
};

class World {
 public:
  std::vector<Body> bodies;
  ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  // the splitting by default: the 3D method that keeps |q| = 1 and a free body's L (sim/README.md)
  Integrator integrator = Integrator::Splitting;
  // q ← q/|q| after every step; off, a four-vector method's |q| drifts as its closed form says
  bool normalizeQuaternions = true;
  double dt = sim::core::settings::kDefaultDt;

  double time = 0.0;
  long steps = 0;

  // advance to exactly tEnd (events at tEnd included); throws Diverged, and std::invalid_argument
  // for dt ≤ 0. The events, the force switches and dt are read when the first call starts the run.
  void advanceTo(double tEnd, StepObserver* observer = nullptr);
  // advance by the steps that advanceTo(tEnd) takes as long as they end by t, never splitting one
  // at t: a picture at t between two of them is drawn from a copy advanced to t (scene_run3d.h)
  void advanceWithin(double t, double tEnd, StepObserver* observer = nullptr);

 private:
  void start();
  void stepTo(double stop, double tEnd, StepObserver* observer);
  void step(double h);
  void applyDueEvents(StepObserver* observer);
  void checkFinite() const;

  bool started_ = false;
  sim::core::StepGrid grid_;
  std::vector<ImpulseEvent> pending_;  // sorted by time
  size_t nextEvent_ = 0;
  States scratch_;
};

}  // namespace sim::world3d

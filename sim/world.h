// The world: bodies, forces and timed impulses, advanced on a fixed step grid that is split
// exactly at every event and force switch (notes: "Dynamics of a free body", "Impulses").
#pragma once

#include <stdexcept>
#include <vector>

#include "body.h"
#include "forces.h"
#include "integrators.h"
#include "settings.h"

namespace sim {

// an impulse j applied at exactly `time`: Δv = j/m, Δω = I⁻¹ (r′ × j)
struct ImpulseEvent {
  double time = 0.0;
  int body = 0;
  Vec2 point = Vec2::Zero();    // body coordinates, or world coordinates when pointInWorld
  bool pointInWorld = false;
  Vec2 impulse = Vec2::Zero();  // world coordinates
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

class World : public Dynamics {
 public:
  std::vector<Body> bodies;
  ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  Integrator integrator = Integrator::SymplecticEuler;
  double dt = settings::kDefaultDt;

  double time = 0.0;
  long steps = 0;

  // advance to exactly tEnd (events at tEnd included); throws Diverged
  void advanceTo(double tEnd, StepObserver* observer = nullptr);

  // the notes' impulse at a world point r: v += j/m, ω += I⁻¹ (r − x) × j
  void applyImpulse(int body, const Vec2& r, const Vec2& j);

  // Dynamics: ẋ = v, θ̇ = ω, v̇ = f/m, ω̇ = τ/I
  void rates(double t, const States& y, Rates& out) const override;

 private:
  void start();
  double nextStop(double tEnd) const;
  void step(double h);
  void applyDueEvents(StepObserver* observer);
  void checkFinite(double t) const;

  bool started_ = false;
  std::vector<ImpulseEvent> pending_;  // sorted by time
  size_t nextEvent_ = 0;
  std::vector<double> switches_;       // sorted force on/off times
  long gridIndex_ = 0;                 // time lies in [gridIndex_ dt, (gridIndex_ + 1) dt)
  double window_ = 0.0;                // a time inside the current step
  mutable std::vector<Vec2> force_;    // scratch for rates()
  mutable std::vector<double> torque_;
  States scratch_;
};

}  // namespace sim

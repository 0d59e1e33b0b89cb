// The world: bodies, forces, timed impulses and contacts, advanced on a fixed step grid that is
// split exactly at every event and force switch (notes: "Dynamics of a free body", "Impulses",
// "Collisions").
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/body.h"
#include "sim/core/forces.h"
#include "sim/core/integrators.h"
#include "sim/core/settings.h"
#include "sim/world/contact.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

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

// bodies overlap where the chosen method cannot start (the event method needs separated bodies)
struct InitialOverlap : std::runtime_error {
  InitialOverlap(int a, int b, double depth);
  int a, b;
  double depth;
};

// why the collision method is what it is (`auto` explains its choice)
enum class MethodReason { Requested, FewBodies, IsolatedImpacts, PersistentContacts };

class World : public Dynamics {
 public:
  std::vector<Body> bodies;
  ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  Integrator integrator = Integrator::SymplecticEuler;
  double dt = settings::kDefaultDt;
  CollisionMethod collisions = CollisionMethod::Auto;  // resolved when the run starts
  MethodReason methodReason = MethodReason::Requested;
  int velocityIterations = settings::kVelocityIterations;
  int positionIterations = settings::kPositionIterations;

  double time = 0.0;
  long steps = 0;
  std::vector<Contact> contacts;       // the touching pairs of the last step
  std::vector<ImpactRecord> impacts;   // every impulse the collision response applied
  std::vector<RestingRecord> resting;  // event method: contacts turned resting (Zeno)

  // resolve `auto`, check the start state; called by advanceTo, callable earlier to ask
  void start();
  // advance to exactly tEnd (events at tEnd included); throws Diverged
  void advanceTo(double tEnd, StepObserver* observer = nullptr);

  // the notes' impulse at a world point r: v += j/m, ω += I⁻¹ (r − x) × j
  void applyImpulse(int body, const Vec2& r, const Vec2& j);

  // Dynamics: ẋ = v, θ̇ = ω, v̇ = f/m, ω̇ = τ/I (with resting-contact forces under `event`)
  void rates(double t, const States& y, Rates& out) const override;

  // manifolds of every pair closer than `margin` now, sorted by pair
  std::vector<Contact> findContacts(double margin) const;
  // the largest extent of the bodies at the start: the scale of the event method's tolerances
  double sceneSize() const { return sceneSize_; }

 private:
  double nextStop(double tEnd) const;
  void step(double h);
  void applyDueEvents(StepObserver* observer);
  void checkFinite(double t) const;

  // the stages the collision methods are made of
  void integrateFree(double h);
  void stepIsolated(double h);
  void stepSequential(double h);
  void stepEvent(double h);

  // isolated (isolated_solver.cpp)
  void resolveDeepestFirst();
  void separateOverlaps();
  // sequential (sequential_solver.cpp)
  void matchWarmStart(std::vector<Contact>& fresh) const;
  void prepareContacts(double h);
  void warmStart();
  void solveVelocities();
  bool solveNormalBlock(Contact& c);
  bool solvePositions();
  // event (event_stepper.cpp)
  struct Impact;
  Impact earliestImpact(const States& from, double span) const;
  void moveAlong(const States& from, double tau);
  void resolveImpactsAt(double t);
  void holdRestingContacts();
  void restingForces(const States& y, std::vector<Vec2>& force, std::vector<double>& torque) const;
  States motion(const States& from, double tau) const;

  bool started_ = false;
  std::vector<ImpulseEvent> pending_;  // sorted by time
  size_t nextEvent_ = 0;
  std::vector<double> switches_;       // sorted force on/off times
  long gridIndex_ = 0;                 // time lies in [gridIndex_ dt, (gridIndex_ + 1) dt)
  double window_ = 0.0;                // a time inside the current step
  double now_ = 0.0;                   // when the impulses being applied happen, for the records
  double sceneSize_ = 1.0;
  bool constantForces_ = true;         // only gravity: the event method moves bodies exactly
  std::vector<std::pair<int, int>> restingPairs_;
  mutable std::vector<Vec2> force_;    // scratch for rates()
  mutable std::vector<double> torque_;
  States scratch_;
};

}  // namespace sim::world

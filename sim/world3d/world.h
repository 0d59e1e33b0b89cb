// The 3D world: rigid bodies, static planes, forces and timed impulses, advanced by one integrator
// on a fixed step grid split exactly at every event and force switch, on the timeline the 2D world
// uses too (sim/core/timeline.h; notes: "Dynamics of a free body", "Impulses", "Collisions"; the
// 3D half of "Representing rigid body state"). The collision method (methods3d.h) decides how a
// step answers touching bodies.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "sim/core/cloned.h"
#include "sim/core/collision_methods.h"
#include "sim/core/diverged.h"
#include "sim/core/rattle_watch.h"
#include "sim/core/settings.h"
#include "sim/core/step_observer.h"
#include "sim/core/timeline.h"
#include "sim/world3d/contact3d.h"
#include "sim/world3d/integrators.h"
#include "sim/world3d/methods3d.h"
#include "sim/world3d/world_def.h"

namespace sim::world3d {

class World;

// told of every finished step and every applied event, e.g. to write a trace
using StepObserver = sim::core::StepObserverOf<World, ImpulseEvent>;

// a method owned by value: a copy of the world has a copy of its method's state
using OwnedMethod3 = sim::core::Cloned<Method3>;

// The 3D world's state, stepped under its definition (world_def.h): the bodies, the time and the
// contacts
class World {
 public:
  World() = default;
  explicit World(WorldDef def, std::vector<Body> bodies = {});

  // what the scene fixed: planes, forces, events, the step, the method asked for and its settings
  const WorldDef& def() const { return def_; }
  // the method stepping the world: the one asked for, with `auto` resolved by start() and switched
  // to sequential when the run shows it is needed; why, and when it switched
  sim::core::CollisionMethod collisions() const { return collisions_; }
  sim::core::MethodReason methodReason() const { return methodReason_; }
  const std::optional<sim::core::MethodSwitch>& methodSwitch() const { return methodSwitch_; }

  std::vector<Body> bodies;
  double time = 0.0;
  long steps = 0;
  std::vector<Contact3> contacts;      // the touching pairs of the last step (sequential)
  std::vector<ImpactRecord3> impacts;  // every impulse the collision response applied

  // resolve `auto` and check dt; called by advanceTo, callable earlier to ask
  void start();
  // advance to exactly tEnd (events at tEnd included); throws sim::core::Diverged, and std::invalid_argument
  // for dt ≤ 0. The events, the force switches and dt are read when the first call starts the run.
  void advanceTo(double tEnd, StepObserver* observer = nullptr);
  // advance by the steps that advanceTo(tEnd) takes as long as they end by t, never splitting one
  // at t: a picture at t between two of them is drawn from a copy advanced to t (scene_run3d.h)
  void advanceWithin(double t, double tEnd, StepObserver* observer = nullptr);

  // every body's state, and the bodies moved to y
  States states() const { return States(bodies.begin(), bodies.end()); }
  void setStates(const States& y);
  // the contacts of every body with every plane and of every two spheres closer than `margin` (at
  // the states y, the bodies' own when none), by pair; restitution and friction combined
  std::vector<Contact3> findContacts(double margin, const States* y = nullptr) const;
  // the largest extent of the bodies at the start: the scale of the event method's tolerances
  double sceneSize() const { return sceneSize_; }
  // some contact can happen: a body and a plane, or two spheres
  bool bodiesCanMeet() const;

 private:
  void chooseMethod();
  // the timeline's two hooks: one step from now to `stop`, arriving at `end` (then the time), and
  // an event's impulse applied now
  template <class>
  friend class sim::core::Timeline;
  void step(double stop, double end);
  void applyEvent(const ImpulseEvent& e);
  void switchToSequential(const sim::core::MethodSwitch& why);
  void checkFinite() const;

  WorldDef def_;
  sim::core::CollisionMethod collisions_ = def_.collisions;
  sim::core::MethodReason methodReason_ = sim::core::MethodReason::Requested;
  std::optional<sim::core::MethodSwitch> methodSwitch_;
  bool started_ = false;
  sim::core::Timeline<ImpulseEvent> timeline_;  // steps of dt cut at the events and force switches, and the events due
  double sceneSize_ = 1.0;
  OwnedMethod3 method_;    // the unit of collisions(), made by start()
  bool watching_ = false;  // `auto` chose event: a contact that persists switches to sequential
  sim::core::RattleWatch rattle_;
};

}  // namespace sim::world3d

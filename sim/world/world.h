// The world: bodies, forces, timed impulses and contacts, advanced on a fixed step grid that is
// split exactly at every event and force switch (the timeline it shares with the 3D world,
// sim/core/timeline.h; notes: "Dynamics of a free body", "Impulses", "Collisions").
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/body.h"
#include "sim/core/diverged.h"
#include "sim/core/forces.h"
#include "sim/core/integrators.h"
#include "sim/core/settings.h"
#include "sim/core/step_observer.h"
#include "sim/core/timeline.h"
#include "sim/world/contact.h"
#include "sim/world/contact_finder.h"
#include "sim/world/contact_watch.h"
#include "sim/world/methods.h"
#include "sim/world/sleep.h"
#include "sim/world/world_def.h"

namespace sim::world {
class WorkerPool;
namespace settings = sim::core::settings;

class World;

// told of every finished step and every applied event, e.g. to write a trace
using StepObserver = sim::core::StepObserverOf<World, ImpulseEvent>;

// bodies overlap where the chosen method cannot start (the event method needs separated bodies)
struct InitialOverlap : std::runtime_error {
  InitialOverlap(int a, int b, double depth);
  int a, b;
  double depth;
};

// the event method gave up: impacts piled up in one step (a stack or a pile is forming)
struct ImpactsPileUp : std::runtime_error {
  ImpactsPileUp(double time, int impacts);
  double time;
};

// The world's state, stepped under its definition (world_def.h): the bodies, the time and the
// contacts; the collision method (methods.h) decides how a step answers touching bodies, and the
// contact finder (contact_finder.h) keeps the contacts' upkeep.
class World {
 public:
  World() = default;
  explicit World(WorldDef def, std::vector<sim::core::Body> bodies = {});

  // what the scene fixed: forces, events, the step, the method asked for and its settings
  const WorldDef& def() const { return def_; }
  // the method stepping the world: the one asked for, with `auto` resolved by start() and switched
  // to the stack solver when the run shows it is needed; why, and when it switched
  sim::core::CollisionMethod collisions() const { return collisions_; }
  sim::core::MethodReason methodReason() const { return methodReason_; }
  const std::optional<sim::core::MethodSwitch>& methodSwitch() const { return methodSwitch_; }

  std::vector<sim::core::Body> bodies;
  double time = 0.0;
  long steps = 0;
  double lastStep = 0.0;               // the length of the last step taken, s: the contacts' impulses are over it
  std::vector<Contact> contacts;       // the touching pairs of the last step
  std::vector<ImpactRecord> impacts;   // every impulse the collision response applied
  std::vector<RestingRecord> resting;  // event method: contacts turned resting (Zeno)

  // resolve `auto`, check the start state; called by advanceTo, callable earlier to ask
  void start();
  // advance to exactly tEnd (events at tEnd included); throws sim::core::Diverged
  void advanceTo(double tEnd, StepObserver* observer = nullptr);
  // advance by the steps that advanceTo(tEnd) takes (grid points, events, force switches, tEnd) as
  // long as they end by t, never splitting one at t: a picture at t between two of them is drawn
  // from a copy of the world advanced to t (render/frame/scene_run.h); throws sim::core::Diverged
  void advanceWithin(double t, double tEnd, StepObserver* observer = nullptr);

  // the notes' impulse at a world point r: v += j/m, ω += I⁻¹ (r − x) × j
  void applyImpulse(int body, const sim::core::Vec2& r, const sim::core::Vec2& j);

  // the notes' free-body equations at time t (notes: "Dynamics of a free body"): ẋ = v, θ̇ = ω,
  // v̇ = f/m, ω̇ = τ/I with the forces and torques of the forces on at t and of the contacts the
  // collision method holds (event: resting contacts)
  void rates(double t, const sim::core::States& y, sim::core::Rates& out) const;

  // every body's state; setStates moves the dynamic bodies to y (static ones never move)
  sim::core::States states() const;
  void setStates(const sim::core::States& y);

  // manifolds of every pair closer than `margin` now, sorted by pair
  std::vector<Contact> findContacts(double margin) const;
  // the solvers' contacts: as findContacts, less the pairs of sleeping bodies with each other and with
  // static ones; a sleeping island that a found contact touches wakes first (its kept contacts back
  // in `contacts`, for the warm start), so that it is solved with what touched it. Each found point
  // starts from the impulses of the same pair's same features in `contacts` (carryImpulses).
  // With `threads`, the bodies are placed and the pairs collided on all of them (the contacts are
  // the same). With nothing asleep the contacts are written over `contacts` where they can be and
  // the two lists' storage swapped: `contacts` is then `found`'s old storage, to be swapped back
  // (as the solvers do: `std::swap(world.contacts, found)`); `found` must be another list.
  // `sideSlack`: the polygon pairs' clipping slack (collide()).
  void findContacts(double margin, std::vector<Contact>& found, WorkerPool* threads = nullptr, double sideSlack = 0.0);
  // the last findContacts(margin, found) found the pairs of the list before it, in the same order
  // (then a solver's arrangement of them still holds); false when it cannot tell
  bool contactPairsKept() const { return contactPairsKept_; }
  // how many of the solver's last findContacts' touching pairs kept their manifold (recycleDistance)
  long recycledContacts() const { return finder_.recycled(); }

  // sleeping (sleep.h): whether a body sleeps now, and how many do
  bool asleep(int body) const { return sleep_.asleep(body); }
  int sleepingBodies() const { return sleep_.sleepingBodies(); }
  // the contacts of the sleeping islands, as they were when each fell asleep (to draw them)
  const std::vector<std::vector<Contact>>& sleepingContacts() const { return sleep_.keptContacts(); }

  // the largest extent of the bodies at the start: the scale of the event method's tolerances
  double sceneSize() const { return sceneSize_; }

 private:
  void measureScene();
  void chooseMethod();
  // the timeline's two hooks: one step from now to `stop`, arriving at `end` (then the time), and
  // an event's impulse applied now
  template <class>
  friend class sim::core::Timeline;
  void step(double stop, double end);
  void applyEvent(const ImpulseEvent& e);
  void switchToStackSolver(const sim::core::MethodSwitch& why);
  void checkFinite(double t) const;
  bool sleeping() const;
  // what a pass of the contact finder asks, the world's contacts being last step's
  ContactQuery contactQuery(double margin, double sideSlack, bool awakeOnly, bool warmStart) const;

  WorldDef def_;
  sim::core::CollisionMethod collisions_ = def_.collisions;
  sim::core::MethodReason methodReason_ = sim::core::MethodReason::Requested;
  std::optional<sim::core::MethodSwitch> methodSwitch_;
  bool started_ = false;
  bool contactPairsKept_ = false;
  sim::core::Timeline<ImpulseEvent> timeline_;  // steps of dt cut at the events and force switches, and the events due
  double sceneSize_ = 1.0;
  Sleep sleep_;         // the islands asleep and the bodies' time at rest
  OwnedMethod method_;  // the unit of collisions(), made by start()
  // `auto` chose event: contact that persists, or a stack forming, switches to sequential
  bool mayStackUp_ = false;
  ContactWatch watch_;
  sim::core::States stepStart_;  // the states where the step began, to redo it on a switch
  // the contacts' upkeep: proxies, broad phase, manifolds, recycling (mutable: a look at the
  // contacts from a const world uses its scratch, and leaves what recycling kept as it was)
  mutable ContactFinder finder_;
  mutable std::vector<sim::core::Vec2> force_;  // scratch of rates()
  mutable std::vector<double> torque_;
};

}  // namespace sim::world

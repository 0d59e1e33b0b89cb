// The world: bodies, forces, timed impulses and contacts, advanced on a fixed step grid that is
// split exactly at every event and force switch (the timeline it shares with the 3D world,
// sim/core/timeline.h; notes: "Dynamics of a free body", "Impulses", "Collisions").
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/collision/collide.h"
#include "sim/collision/pair_cache.h"
#include "sim/core/body.h"
#include "sim/core/forces.h"
#include "sim/core/integrators.h"
#include "sim/core/settings.h"
#include "sim/core/timeline.h"
#include "sim/world/contact.h"
#include "sim/world/contact_recycle.h"
#include "sim/world/contact_watch.h"
#include "sim/world/methods.h"
#include "sim/world/sleep.h"

namespace sim::world {
class WorkerPool;
namespace settings = sim::core::settings;

// an impulse j applied at exactly `time`: Δv = j/m, Δω = I⁻¹ (r′ × j)
struct ImpulseEvent {
  double time = 0.0;
  int body = 0;
  sim::core::Vec2 point = sim::core::Vec2::Zero();  // body coordinates, or world coordinates when pointInWorld
  bool pointInWorld = false;
  sim::core::Vec2 impulse = sim::core::Vec2::Zero();  // world coordinates
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

// the event method gave up: impacts piled up in one step (a stack or a pile is forming)
struct ImpactsPileUp : std::runtime_error {
  ImpactsPileUp(double time, int impacts);
  double time;
};

// The world holds the bodies, the forces, the contacts and the time; the collision method
// (methods.h) decides how a step answers touching bodies.
class World {
 public:
  std::vector<sim::core::Body> bodies;
  sim::core::ForceSet forces;
  std::vector<ImpulseEvent> events;  // any order; applied in time order
  sim::core::Integrator integrator = sim::core::Integrator::SymplecticEuler;
  double dt = settings::kDefaultDt;                                          // read once, by start(): the step grid's spacing
  sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto;  // resolved when the run starts
  sim::core::MethodReason methodReason = sim::core::MethodReason::Requested;
  std::optional<sim::core::MethodSwitch> methodSwitch;  // when and why `auto` went from event to the stack solver
  int velocityIterations = settings::kVelocityIterations;
  int positionIterations = settings::kPositionIterations;
  int substeps = settings::kSubsteps;             // soft_step: substeps per step
  double contactHertz = settings::kContactHertz;  // soft_step: contact stiffness, Hz (capped per substep)
  // soft_step: the widest SIMD a set's contacts are solved with, where the processor has it: 8
  // (AVX-512: eight doubles at once; eight floats with its registers), 4 (AVX2: four doubles, eight
  // floats) or 1 (one at a time); the same order, to the same state
  int simdWidth = 8;
  // soft_step: the numbers its contact solve is carried in (the world's state stays double)
  Precision precision = Precision::Double;
  // sequential and soft_step: islands at rest fall asleep and are not stepped until touched (sleep.h)
  bool sleep = false;
  // soft_step: threads that share each set of contacts (the same state with any number)
  int threads = 1;
  // soft_step: a touching pair keeps its manifold, carried with the bodies, while it moved less than
  // this relative to the step it was made in, m (contact_recycle.h); 0: every pair collided every step
  double recycleDistance = 0.0;

  double time = 0.0;
  long steps = 0;
  double lastStep = 0.0;               // the length of the last step taken, s: the contacts' impulses are over it
  std::vector<Contact> contacts;       // the touching pairs of the last step
  std::vector<ImpactRecord> impacts;   // every impulse the collision response applied
  std::vector<RestingRecord> resting;  // event method: contacts turned resting (Zeno)

  // resolve `auto`, check the start state; called by advanceTo, callable earlier to ask
  void start();
  // advance to exactly tEnd (events at tEnd included); throws Diverged
  void advanceTo(double tEnd, StepObserver* observer = nullptr);
  // advance by the steps that advanceTo(tEnd) takes (grid points, events, force switches, tEnd) as
  // long as they end by t, never splitting one at t: a picture at t between two of them is drawn
  // from a copy of the world advanced to t (render/frame/scene_run.h); throws Diverged
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
  long recycledContacts() const;

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
  // the manifolds into `found` (its entries overwritten, its storage kept), without the sleeping pairs when
  // `awakeOnly`, warm started from `contacts` when `warmStart`; the placing and the narrow phase
  // split between `threads` when there are two or more. `lastStep` (`contacts`, or none): a list
  // the contacts may be written over while its pairs are theirs (then its storage and found's swap)
  // Returns whether the pairs were lastStep's, each written over its own. `sideSlack` as collide()'s.
  bool collectContacts(double margin, std::vector<Contact>& found, bool awakeOnly, bool warmStart, WorkerPool* threads = nullptr,
                       std::vector<Contact>* lastStep = nullptr, double sideSlack = 0.0) const;
  // collectContacts' stages (world.cpp)
  class ContactPass;

  bool started_ = false;
  bool contactPairsKept_ = false;
  sim::core::Timeline<ImpulseEvent> timeline_;  // steps of dt cut at the events and force switches, and the events due
  double sceneSize_ = 1.0;
  Sleep sleep_;         // the islands asleep and the bodies' time at rest
  OwnedMethod method_;  // the unit of `collisions`, made by start()
  // `auto` chose event: contact that persists, or a stack forming, switches to sequential
  bool mayStackUp_ = false;
  ContactWatch watch_;
  sim::core::States stepStart_;  // the states where the step began, to redo it on a switch
  // the collision proxies, one per convex shape, body by body (a body of parts has one per part):
  // empty while every body is one shape, when proxy i is body i
  struct Proxy {
    int body = 0, part = 0;
  };
  void makeProxies() const;
  mutable std::vector<Proxy> proxies_;
  mutable size_t proxiesFor_ = 0;  // the body count they were made for
  // the broad phase's candidate pairs, kept from one findContacts to the next (the pairs found
  // do not depend on them)
  mutable sim::collision::PairCache pairCache_;
  // soft_step's contact recycling: each candidate pair's manifold as made, by the index of its pair
  // (recycle_, for the pairs recycleKeys_), and the list of this call's pairs when they are others
  // (recycleNext_, swapped in at the next call); which pairs kept theirs; each proxy's reach
  mutable std::vector<RecycleEntry> recycle_, recycleNext_;
  mutable std::vector<std::uint64_t> recycleKeys_, keysNow_;
  mutable std::vector<char> recycledNow_;
  mutable std::vector<double> extent_;
  mutable bool recycleReady_ = false;
  mutable std::vector<std::pair<int, int>> pairs_;           // scratch of findContacts: the proxies' pairs,
  mutable std::vector<sim::collision::PlacedShape> placed_;  // and the proxies' shapes where they are,
  mutable std::vector<sim::collision::Aabb> boxes_;          // their bounds with the margin,
  mutable std::vector<bool> fixed_;                          // which are static,
  mutable std::vector<sim::collision::Manifold> manifolds_;  // and each pair's manifold, when threads share them,
  mutable std::vector<int> touching_;                        // with where each thread's touching pairs begin,
  mutable std::vector<char> differs_;                        // and whether its pairs differ from last step's
  mutable std::vector<sim::core::Vec2> force_;               // scratch of rates()
  mutable std::vector<double> torque_;
};

}  // namespace sim::world

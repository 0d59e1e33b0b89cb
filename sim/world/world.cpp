#include "sim/world/world.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "sim/world/method_models.h"
#include "sim/world/worker_pool.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

ImpactsPileUp::ImpactsPileUp(double t, int n)
    : std::runtime_error("more than " + std::to_string(n) + " impacts in one step at t = " + std::to_string(t) +
                         ": impacts pile up; use --collisions sequential"),
      time(t) {}

InitialOverlap::InitialOverlap(int a_, int b_, double d)
    : std::runtime_error("bodies overlap at the start"), a(a_), b(b_), depth(d) {}

World::World(WorldDef def, std::vector<Body> bodies_)
    : bodies(std::move(bodies_)), def_(std::move(def)), timeline_(def_.dt, def_.events, def_.forces.breakpoints()) {}

void World::applyImpulse(int i, const Vec2& r, const Vec2& j) {
  Body& b = bodies[i];
  b.v += b.invMass * j;
  b.omega += b.invInertia * cross(r - b.x, j);
}

void World::rates(double t, const States& y, Rates& out) const {
  // forces and torques: the applied forces on at t, and what the method's contacts push with
  def_.forces.accumulate(t, bodies, y, force_, torque_);
  if (method_) method_->addContactForces(*this, y, force_, torque_);
  // ẋ = v, θ̇ = ω, v̇ = f/m, ω̇ = τ/I
  out.resize(y.size());
  for (size_t i = 0; i < y.size(); ++i) {
    const Body& b = bodies[i];
    if (b.isStatic || sleep_.asleep(static_cast<int>(i))) {
      out[i] = BodyRate{};
      continue;
    }
    out[i] = {y[i].v, y[i].omega, b.invMass * force_[i], b.invInertia * torque_[i]};
  }
}

States World::states() const {
  States y(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) y[i] = bodies[i].state();
  return y;
}

void World::setStates(const States& y) {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].isStatic) bodies[i].setState(y[i]);
}

std::vector<Contact> World::findContacts(double margin) const {
  std::vector<Contact> found;
  (void)finder_.collect(contactQuery(margin, 0.0, false, false), found);
  return found;
}

void World::findContacts(double margin, std::vector<Contact>& found, WorkerPool* threads, double sideSlack) {
  assert(&found != &contacts && "findContacts writes over `contacts`: give it another list");
  const bool skip = sleeping() && sleep_.sleepingBodies() > 0;
  // when every body that can move sleeps, nothing touches anything awake: not even the broad phase
  contactPairsKept_ = false;
  if (skip && sleep_.sleepingBodies() == std::count_if(bodies.begin(), bodies.end(), [](const Body& b) { return !b.isStatic; })) {
    found.clear();
    return;
  }
  // (with nothing asleep, the contacts that stay are written over last step's: wakeTouched reads
  // last step's list whole)
  contactPairsKept_ = finder_.collect(contactQuery(margin, sideSlack, skip, true), found, threads, skip ? nullptr : &contacts);
  // sleeping islands that an awake body touches wake before the solve (Box2D v3 wakes a solver set
  // when a contact begins touching it), and their own contacts are found with them (and may touch
  // another island)
  while (skip && sleep_.wakeTouched(found, contacts))
    (void)finder_.collect(contactQuery(margin, sideSlack, sleep_.sleepingBodies() > 0, true), found, threads);
}

ContactQuery World::contactQuery(double margin, double sideSlack, bool awakeOnly, bool warmStart) const {
  // (recycling is soft_step's: the other methods collide every pair every step)
  const double recycle = collisions_ == CollisionMethod::SoftStep ? def_.recycleDistance : 0.0;
  return ContactQuery{bodies, sleep_, contacts, margin, sideSlack, recycle, awakeOnly, warmStart};
}

void World::start() {
  if (started_) return;
  measureScene();
  if (collisions_ == CollisionMethod::Auto) chooseMethod();
  method_ = OwnedMethod(makeMethod(collisions_, def_.precision));
  method_->start(*this);
  started_ = true;
}

// the scale of the event method's tolerances: the extent of everything finite at the start
void World::measureScene() {
  Aabb all{Vec2::Constant(std::numeric_limits<double>::infinity()), Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const Body& b : bodies) {
    if (b.shape.kind == ShapeKind::Plane) continue;
    const Aabb box = bounds(b.shape, b.pose());
    all.lower = all.lower.cwiseMin(box.lower);
    all.upper = all.upper.cwiseMax(box.upper);
  }
  if (all.upper.x() >= all.lower.x()) sceneSize_ = std::max((all.upper - all.lower).maxCoeff(), settings::kMinSceneSize);
}

// `auto`: the least model the scene needs at the start (method_models.h); what the run then shows
// it needs (contact that persists) is watched for step by step (World::step)
void World::chooseMethod() {
  size_t dynamic = 0;
  for (const Body& b : bodies) dynamic += !b.isStatic;
  const bool loaded = def_.forces.gravity != Vec2::Zero() || !def_.forces.gravityOnly();
  unsigned needs = 0;
  if (dynamic > 0 && bodies.size() >= 2) needs |= bit(Phenomenon::IsolatedImpacts);
  // bodies that touch at the start under a load rest on each other: their contacts persist
  if (needs && loaded && !findContacts(settings::kContactMargin).empty()) needs |= bit(Phenomenon::RestingContact);
  collisions_ = leastMethodFor(needs);
  if (!needs) methodReason_ = MethodReason::FewBodies;
  else if (has(needs, Phenomenon::RestingContact)) methodReason_ = MethodReason::PersistentContacts;
  else methodReason_ = MethodReason::IsolatedImpacts;
  mayStackUp_ = collisions_ == CollisionMethod::Event;
}

std::unique_ptr<Method> makeMethod(CollisionMethod method, Precision precision) {
  switch (method) {
    case CollisionMethod::Auto:  // resolved by World::start
    case CollisionMethod::None: return makeFreeMotion();
    case CollisionMethod::Isolated: return makeIsolatedSolver();
    case CollisionMethod::Sequential: return makeSequentialSolver();
    case CollisionMethod::SoftStep: return makeSoftStepSolver(precision);
    case CollisionMethod::Event: return makeEventStepper();
  }
  return makeFreeMotion();
}

void World::advanceTo(double tEnd, StepObserver* observer) { timeline_.advanceTo(*this, tEnd, observer); }

void World::advanceWithin(double t, double tEnd, StepObserver* observer) { timeline_.advanceWithin(*this, t, tEnd, observer); }

// the timeline's step (timeline.h): one step of size h by the collision method (methods.h), and
// what is the world's around it: sleeping, `auto`'s switch and the finiteness check. Under
// `auto`, when the event method finds impacts piling up (a stack or a pile forming), the step is
// done again from where it began by the stack solver, which goes on from there.
void World::step(double stop, double end) {
  const double h = stop - time;
  const TimeStep thisStep{time, h};
  // a point force on during the step wakes the island it pushes
  if (sleeping()) sleep_.wakeForced(def_.forces, thisStep.midpoint(), contacts);
  if (!mayStackUp_) {
    method_->step(*this, thisStep);
  } else {
    stepStart_ = states();
    const size_t impactsBefore = impacts.size(), restingBefore = resting.size();
    try {
      method_->step(*this, thisStep);
      // a contact that persists (contact_watch.h) is the resting-contact solver's from the step's end
      if (const std::optional<PersistentContact> p = watch_.afterStep(*this, impactsBefore, restingBefore))
        switchToStackSolver({end, p->a, p->b, p->how});
    } catch (const ImpactsPileUp&) {
      setStates(stepStart_);
      // what the undone attempt recorded did not happen
      impacts.resize(impactsBefore);
      resting.resize(restingBefore);
      switchToStackSolver({thisStep.start});
      method_->step(*this, thisStep);
    }
  }
  ++steps;
  lastStep = h;
  // the islands at rest long enough fall asleep
  if (sleeping()) sleep_.afterStep(bodies, contacts, def_.forces, thisStep.midpoint(), h);
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite(time + h);
  time = end;
}

// the stack solver from why.time on: the start of the step in which the impacts piled up, or the
// end of the one in which a contact persisted
void World::switchToStackSolver(const MethodSwitch& why) {
  collisions_ = CollisionMethod::Sequential;
  methodReason_ = why.a < 0 ? MethodReason::StackFormed : MethodReason::ContactPersisted;
  methodSwitch_ = why;
  mayStackUp_ = false;
  contacts.clear();
  method_ = OwnedMethod(makeMethod(collisions_, def_.precision));
  method_->start(*this);
}

// the timeline's event (timeline.h): the impulse now, its body's island woken first
void World::applyEvent(const ImpulseEvent& e) {
  if (sleeping()) sleep_.wake(e.body, contacts);
  const Body& b = bodies[e.body];
  const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
  applyImpulse(e.body, r, e.impulse);
}

// only the stack solvers sleep: the event method's impacts and the isolated impulses find their
// own contacts, which a sleeping body would ignore
bool World::sleeping() const {
  return def_.sleep && (collisions_ == CollisionMethod::Sequential || collisions_ == CollisionMethod::SoftStep);
}

void World::checkFinite(double t) const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !std::isfinite(b.angle) || !isFinite(b.v) || !std::isfinite(b.omega))
      throw Diverged(t, static_cast<int>(i));
  }
}

}  // namespace sim::world

#include "sim/world/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sim/collision/broad_phase.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

Diverged::Diverged(double t, int b)
    : std::runtime_error("state is no longer finite at t = " + std::to_string(t)), time(t), body(b) {}

InitialOverlap::InitialOverlap(int a_, int b_, double d)
    : std::runtime_error("bodies overlap at the start"), a(a_), b(b_), depth(d) {}

void World::applyImpulse(int i, const Vec2& r, const Vec2& j) {
  Body& b = bodies[i];
  b.v += b.invMass * j;
  b.omega += b.invInertia * cross(r - b.x, j);
}

void World::rates(double, const States& y, Rates& out) const {
  forces.accumulate(window_, bodies, y, force_, torque_);
  // resting contacts push back with whatever force keeps them from sinking in
  if (!restingPairs_.empty()) restingForces(y, force_, torque_);
  out.resize(y.size());
  for (size_t i = 0; i < y.size(); ++i) {
    const Body& b = bodies[i];
    if (b.isStatic) {
      out[i] = BodyRate{};
      continue;
    }
    out[i] = {y[i].v, y[i].omega, b.invMass * force_[i], b.invInertia * torque_[i]};
  }
}

std::vector<Contact> World::findContacts(double margin) const {
  std::vector<Aabb> boxes;
  std::vector<bool> fixed;
  for (const Body& b : bodies) {
    Aabb box = bounds(b.shape, b.pose());
    box.lower -= Vec2::Constant(margin);
    box.upper += Vec2::Constant(margin);
    boxes.push_back(box);
    fixed.push_back(b.isStatic);
  }
  std::vector<Contact> found;
  for (const auto& [i, j] : overlappingPairs(boxes, fixed)) {
    const Body &a = bodies[i], &b = bodies[j];
    Contact c;
    c.a = i, c.b = j;
    c.manifold = collide(a.shape, a.pose(), b.shape, b.pose(), margin);
    if (c.manifold.count == 0) continue;
    c.restitution = combinedRestitution(a.restitution, b.restitution);
    c.friction = combinedFriction(a.friction, b.friction);
    found.push_back(c);
  }
  return found;
}

void World::start() {
  if (started_) return;
  pending_ = events;
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const ImpulseEvent& a, const ImpulseEvent& b) { return a.time < b.time; });
  switches_ = forces.breakpoints();
  std::sort(switches_.begin(), switches_.end());
  constantForces_ = forces.pointForces.empty() && forces.springs.empty() && forces.drags.empty();

  // the scale of the event method's tolerances: the extent of everything finite at the start
  Aabb all{Vec2::Constant(std::numeric_limits<double>::infinity()), Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (const Body& b : bodies) {
    if (b.shape.kind == ShapeKind::Plane) continue;
    const Aabb box = bounds(b.shape, b.pose());
    all.lower = all.lower.cwiseMin(box.lower);
    all.upper = all.upper.cwiseMax(box.upper);
  }
  if (all.upper.x() >= all.lower.x()) sceneSize_ = std::max((all.upper - all.lower).maxCoeff(), settings::kMinSceneSize);

  // `auto`: the least model the scene needs
  if (collisions == CollisionMethod::Auto) {
    size_t dynamic = 0;
    for (const Body& b : bodies) dynamic += !b.isStatic;
    const bool loaded = forces.gravity != Vec2::Zero() || !constantForces_;
    if (dynamic == 0 || bodies.size() < 2) {
      collisions = CollisionMethod::None;
      methodReason = MethodReason::FewBodies;
    } else if (loaded && !findContacts(settings::kContactMargin).empty()) {
      collisions = CollisionMethod::Sequential;
      methodReason = MethodReason::PersistentContacts;
    } else {
      collisions = CollisionMethod::Event;
      methodReason = MethodReason::IsolatedImpacts;
    }
  }
  // the event method advances to the instant of touching: it cannot start from an overlap
  if (collisions == CollisionMethod::Event)
    for (const Contact& c : findContacts(0.0))
      if (c.manifold.separation < -settings::kTouchingTolerance * sceneSize_)
        throw InitialOverlap(c.a, c.b, -c.manifold.separation);
  started_ = true;
}

// the next time to stop at: the next grid point, event, force switch or the end, whichever is first
double World::nextStop(double tEnd) const {
  double stop = std::min(tEnd, (gridIndex_ + 1) * dt);
  if (nextEvent_ < pending_.size()) stop = std::min(stop, pending_[nextEvent_].time);
  auto sw = std::upper_bound(switches_.begin(), switches_.end(), time + settings::kTimeSnap * dt);
  if (sw != switches_.end()) stop = std::min(stop, *sw);
  return stop;
}

void World::advanceTo(double tEnd, StepObserver* observer) {
  start();
  applyDueEvents(observer);
  while (time < tEnd - settings::kTimeSnap * dt) {
    const double stop = nextStop(tEnd);
    const double grid = (gridIndex_ + 1) * dt;
    step(stop - time);
    // land on the grid point itself when the stop is (within round-off) the grid point
    if (std::abs(stop - grid) <= settings::kTimeSnap * dt) {
      ++gridIndex_;
      time = std::abs(stop - tEnd) <= settings::kTimeSnap * dt ? tEnd : grid;
    } else {
      time = stop;
    }
    if (observer) observer->afterStep(*this);
    applyDueEvents(observer);
  }
  time = std::max(time, tEnd);
}

// one step of size h: each collision method is a short list of named stages
void World::step(double h) {
  window_ = time + 0.5 * h;
  switch (collisions) {
    case CollisionMethod::Auto:  // resolved by start()
    case CollisionMethod::None: integrateFree(h); break;
    case CollisionMethod::Isolated: stepIsolated(h); break;
    case CollisionMethod::Sequential: stepSequential(h); break;
    case CollisionMethod::Event: stepEvent(h); break;
  }
  ++steps;
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite(time + h);
}

// move every body by the integrator over h, as if nothing touched
void World::integrateFree(double h) {
  scratch_.resize(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) scratch_[i] = bodies[i].state();
  integrate(integrator, *this, time, h, scratch_);
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].isStatic) bodies[i].setState(scratch_[i]);
}

// the notes' model: move freely, then find the overlaps and answer each with one impulse
void World::stepIsolated(double h) {
  now_ = time + h;
  integrateFree(h);
  contacts = findContacts(0.0);
  resolveDeepestFirst();
  separateOverlaps();
}

void World::applyDueEvents(StepObserver* observer) {
  while (nextEvent_ < pending_.size() && pending_[nextEvent_].time <= time + settings::kTimeSnap * dt) {
    const ImpulseEvent& e = pending_[nextEvent_++];
    const Body& b = bodies[e.body];
    const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
    applyImpulse(e.body, r, e.impulse);
    if (observer) observer->afterEvent(*this, e);
  }
}

void World::checkFinite(double t) const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !std::isfinite(b.angle) || !isFinite(b.v) || !std::isfinite(b.omega))
      throw Diverged(t, static_cast<int>(i));
  }
}

}  // namespace sim::world

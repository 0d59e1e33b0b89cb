#include "sim/world3d/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "sim/world3d/collide3d.h"
#include "sim/world3d/method_models3d.h"

namespace sim::world3d {
using namespace sim::core;
namespace core = sim::core;

ContactPersists::ContactPersists(double t, int a_, int b_, const std::string& why)
    : std::runtime_error(why), time(t), a(a_), b(b_) {}

World::World(WorldDef def, std::vector<Body> bodies_)
    : bodies(std::move(bodies_)), def_(std::move(def)), timeline_(def_.dt, def_.events, def_.forces.breakpoints()) {}

void World::start() {
  if (started_) return;
  const double dt = def_.dt;
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("the time step dt must be a positive finite number");
  // the scale of the event method's tolerances: the bodies' extent at the start
  double extent = 0.0;
  for (const Body& b : bodies) extent = std::max(extent, 2.0 * boundingRadius(b.shape));
  sceneSize_ = std::max(extent, core::settings::kMinSceneSize);
  if (collisions_ == CollisionMethod::Auto) chooseMethod();
  method_ = OwnedMethod3(makeMethod3(collisions_));
  method_->start(*this);
  started_ = true;
}

bool World::bodiesCanMeet() const {
  int spheres = 0;
  for (const Body& b : bodies) spheres += b.shape.kind == ShapeKind::Sphere;
  return (!def_.planes.empty() && !bodies.empty()) || spheres >= 2;
}

// `auto`: the least model the scene needs at the start (method_models3d.h), then watched
void World::chooseMethod() {
  unsigned needs = 0;
  if (bodiesCanMeet()) needs |= core::bit(core::Phenomenon::IsolatedImpacts);
  // bodies that touch at the start under a load rest: their contacts persist
  const ForceSet& forces = def_.forces;
  const bool loaded = forces.gravity != Vec3::Zero() || !forces.pointForces.empty() || !forces.springs.empty();
  if (needs && loaded && !findContacts(core::settings::kContactMargin).empty())
    needs |= core::bit(core::Phenomenon::RestingContact);
  collisions_ = leastMethodFor3(needs);
  if (!needs) methodReason_ = MethodReason::FewBodies;
  else if (core::has(needs, core::Phenomenon::RestingContact)) methodReason_ = MethodReason::PersistentContacts;
  else methodReason_ = MethodReason::IsolatedImpacts;
  watching_ = collisions_ == CollisionMethod::Event;
}

void World::setStates(const States& y) {
  for (size_t i = 0; i < bodies.size(); ++i) bodies[i].setState(y[i]);
}

namespace {
// the pairs of spheres within `margin`, as (i, j) with i < j, in the order of the bodies (the order
// the contacts were always found in, so that a solver's sweep over them stays the same): a hashed
// grid of cells as wide as the largest sphere plus the margin (Ericson 7.1), each sphere tested
// against the spheres of its own and the 26 cells around it
std::vector<std::pair<int, int>> spherePairsNear(const std::vector<Body>& bodies, const auto& at, double margin) {
  std::vector<int> spheres;
  double largest = 0.0;
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].shape.kind == ShapeKind::Sphere)
      spheres.push_back(static_cast<int>(i)), largest = std::max(largest, bodies[i].shape.radius);
  const double cell = 2.0 * largest + std::max(margin, 0.0);
  std::vector<std::pair<int, int>> pairs;
  const auto cellOf = [&](int i, int axis) { return std::floor(at(i).x[axis] / cell); };
  // a cell index that a 64-bit key cannot hold (or an unbounded margin): every pair, as before
  bool gridded = std::isfinite(cell) && cell > 0.0;
  for (const int i : spheres)
    for (int axis = 0; axis < 3 && gridded; ++axis) gridded = std::abs(cellOf(i, axis)) < 1e6;
  if (!gridded) {
    for (size_t k = 0; k < spheres.size(); ++k)
      for (size_t l = k + 1; l < spheres.size(); ++l) pairs.emplace_back(spheres[k], spheres[l]);
    return pairs;
  }
  const auto key = [](long long cx, long long cy, long long cz) { return (cx * 2000003LL + cy) * 2000003LL + cz; };
  std::unordered_map<long long, std::vector<int>> grid;
  for (const int i : spheres)
    grid[key(static_cast<long long>(cellOf(i, 0)), static_cast<long long>(cellOf(i, 1)), static_cast<long long>(cellOf(i, 2)))]
        .push_back(i);
  for (const int i : spheres) {
    const size_t first = pairs.size();
    const long long cx = static_cast<long long>(cellOf(i, 0)), cy = static_cast<long long>(cellOf(i, 1)),
                    cz = static_cast<long long>(cellOf(i, 2));
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (found == grid.end()) continue;
          for (const int j : found->second)
            if (j > i) pairs.emplace_back(i, j);
        }
    std::sort(pairs.begin() + static_cast<long>(first), pairs.end());
  }
  return pairs;
}
}  // namespace

std::vector<Contact3> World::findContacts(double margin, const States* y) const {
  const auto at = [&](size_t i) -> const BodyState& { return y ? (*y)[i] : bodies[i]; };
  // (spheres alone meet other bodies: the scene reader refuses other pairs that could)
  const std::vector<std::pair<int, int>> near = spherePairsNear(bodies, at, margin);
  auto next = near.begin();
  std::vector<Contact3> found;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& body = bodies[i];
    for (size_t p = 0; p < def_.planes.size(); ++p) {
      Contact3 c;
      c.count = planeContact(body.shape, at(i), def_.planes[p], margin, c.points);
      if (c.count == 0) continue;
      c.a = static_cast<int>(i), c.b = -1 - static_cast<int>(p);
      c.normal = def_.planes[p].normal;
      c.restitution = combinedRestitution(body.restitution, def_.planes[p].restitution);
      c.friction = combinedFriction(body.friction, body.frictionNamed, def_.planes[p].friction, def_.planes[p].frictionNamed);
      found.push_back(c);
    }
    for (; next != near.end() && next->first == static_cast<int>(i); ++next) {
      const Body& other = bodies[next->second];
      Contact3 c;
      if (!sphereContact(at(i), body.shape.radius, at(next->second), other.shape.radius, margin, c.points[0], c.normal)) continue;
      c.a = static_cast<int>(i), c.b = next->second, c.count = 1;
      c.restitution = combinedRestitution(body.restitution, other.restitution);
      c.friction = combinedFriction(body.friction, body.frictionNamed, other.friction, other.frictionNamed);
      found.push_back(c);
    }
  }
  return found;
}

void World::advanceTo(double tEnd, StepObserver* observer) { timeline_.advanceTo(*this, tEnd, observer); }

void World::advanceWithin(double t, double tEnd, StepObserver* observer) { timeline_.advanceWithin(*this, t, tEnd, observer); }

// the timeline's step (timeline.h): one step by the collision method, then the finiteness check.
// Under `auto`, a contact the event method cannot carry on (ContactPersists) makes sequential redo
// the step from where it began, and slow impacts repeated at one pair (the rattle watch) hand the
// run to it from the step's end
void World::step(double stop, double end) {
  const double stepStart = time, h = stop - time;
  if (!watching_) {
    method_->step(*this, stepStart, h);
  } else {
    const States from = states();
    const size_t impactsBefore = impacts.size();
    try {
      method_->step(*this, stepStart, h);
      for (size_t k = impactsBefore; k < impacts.size(); ++k) {
        const ImpactRecord3& r = impacts[k];
        if (!rattle_.impact(r.a, r.b, r.t, r.vnBefore, core::settings::kTouchingTolerance * sceneSize_)) continue;
        switchToSequential({end, r.a, r.b, core::Persistence::Rattling});
        break;
      }
    } catch (const ContactPersists& p) {
      setStates(from);
      impacts.resize(impactsBefore);
      switchToSequential({stepStart, p.a, p.b, core::Persistence::Rested});
      method_->step(*this, stepStart, h);
    }
  }
  ++steps;
  time = end;
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite();
}

void World::switchToSequential(const MethodSwitch& why) {
  collisions_ = CollisionMethod::Sequential;
  methodReason_ = MethodReason::ContactPersisted;
  methodSwitch_ = why;
  watching_ = false;
  contacts.clear();
  method_ = OwnedMethod3(makeMethod3(collisions_));
  method_->start(*this);
}

// the timeline's event (timeline.h): the impulse now
void World::applyEvent(const ImpulseEvent& e) {
  Body& b = bodies[e.body];
  b.applyImpulse(e.pointInWorld ? e.point : b.toWorld(e.point), e.impulse);
}

void World::checkFinite() const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !isFinite(b.q) || !isFinite(b.v) || !isFinite(b.omega)) throw Diverged(time, static_cast<int>(i));
  }
}

// --- free motion: the `none` method, and the first stage of the others ---

namespace {

class FreeMotion3 final : public Method3 {
 public:
  std::unique_ptr<Method3> clone() const override { return std::make_unique<FreeMotion3>(*this); }
  void step(World& world, double start, double h) override { moveFreely(world, start, h); }
};

}  // namespace

std::unique_ptr<Method3> makeFreeMotion3() { return std::make_unique<FreeMotion3>(); }

States motion(const World& world, const States& from, double start, double h, double tau) {
  States y = from;
  if (tau <= 0.0) return y;
  // the timed forces that are on somewhere inside the step are on for all of it (it is split at
  // every switch)
  const Dynamics dynamics{world.bodies, world.def().forces, start + 0.5 * h};
  integrate(world.def().integrator, dynamics, tau, y);
  if (world.def().normalizeQuaternions) normalizeRotations(y);
  return y;
}

void moveFreely(World& world, double start, double h) { world.setStates(motion(world, world.states(), start, h, h)); }

}  // namespace sim::world3d

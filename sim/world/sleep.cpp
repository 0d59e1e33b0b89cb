#include "sim/world/sleep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "sim/core/settings.h"

namespace sim::world {
using namespace sim::core;

namespace {

bool byPair(const Contact& x, const Contact& y) { return pairKey(x) < pairKey(y); }
bool samePair(const Contact& x, const Contact& y) { return pairKey(x) == pairKey(y); }

bool pushing(const PointForce& f, double t) { return f.from <= t && t < f.until && f.force != Vec2::Zero(); }

}  // namespace

int Sleep::root(int body) {
  while (parent_[body] != body) body = parent_[body] = parent_[parent_[body]];
  return body;
}

void Sleep::join(int a, int b) {
  a = root(a), b = root(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);
}

void Sleep::afterStep(std::vector<Body>& bodies, const std::vector<Contact>& contacts, const ForceSet& forces, double t,
                      double h) {
  const int n = static_cast<int>(bodies.size());
  atRest_.resize(n, 0.0);
  island_.resize(n, -1);
  auto awake = [&](int i) { return !bodies[i].isStatic && island_[i] < 0; };
  // each awake body's time at rest (Box2D: both speeds below their tolerances), none under a push
  for (int i = 0; i < n; ++i) {
    if (!awake(i)) continue;
    const Body& b = bodies[i];
    const bool slow = b.v.squaredNorm() <= settings::kSleepLinearSpeed * settings::kSleepLinearSpeed &&
                      std::abs(b.omega) <= settings::kSleepAngularSpeed;
    atRest_[i] = slow ? atRest_[i] + h : 0.0;
  }
  for (const PointForce& f : forces.pointForces)
    if (pushing(f, t) && awake(f.body)) atRest_[f.body] = 0.0;
  // the islands: awake bodies joined by the step's contacts and by springs, never through a static body
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  for (const Contact& c : contacts)
    if (awake(c.a) && awake(c.b)) join(c.a, c.b);
  for (const Spring& s : forces.springs)
    if (s.bodyB != kWorldAnchor && awake(s.bodyA) && awake(s.bodyB)) join(s.bodyA, s.bodyB);
  // an island sleeps when its least rested body has rested long enough
  islandRest_.assign(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i)
    if (awake(i)) islandRest_[root(i)] = std::min(islandRest_[root(i)], atRest_[i]);
  if (sleeping_ == 0) members_.clear(), kept_.clear();
  const int firstNew = static_cast<int>(members_.size());
  for (int i = 0; i < n; ++i) {
    if (!awake(i) || islandRest_[root(i)] < settings::kTimeToSleep) continue;
    // the island's number is its root's (the island's lowest body, so met first)
    const int r = root(i);
    if (r == i) {
      members_.emplace_back();
      kept_.emplace_back();
      island_[i] = static_cast<int>(members_.size()) - 1;
    } else {
      island_[i] = island_[r];
    }
    members_[island_[i]].push_back(i);
    bodies[i].v.setZero();
    bodies[i].omega = 0.0;
    ++sleeping_;
  }
  if (static_cast<int>(members_.size()) == firstNew) return;
  // the new islands' contacts, kept as they were (with their impulses) to warm start their wake
  for (const Contact& c : contacts) {
    const int body = bodies[c.a].isStatic ? c.b : c.a;
    if (island_[body] >= firstNew) kept_[island_[body]].push_back(c);
  }
}

void Sleep::wake(int body, std::vector<Contact>& contacts) {
  if (!asleep(body)) return;
  const int id = island_[body];
  for (int m : members_[id]) island_[m] = -1, atRest_[m] = 0.0;
  sleeping_ -= static_cast<int>(members_[id].size());
  members_[id].clear();
  const auto middle = static_cast<std::ptrdiff_t>(contacts.size());
  contacts.insert(contacts.end(), kept_[id].begin(), kept_[id].end());
  std::inplace_merge(contacts.begin(), contacts.begin() + middle, contacts.end(), byPair);
  // an island that fell asleep at the end of last step still has its contacts among last step's
  contacts.erase(std::unique(contacts.begin(), contacts.end(), samePair), contacts.end());
  kept_[id].clear();
}

void Sleep::wakeForced(const ForceSet& forces, double t, std::vector<Contact>& contacts) {
  if (sleeping_ == 0) return;
  for (const PointForce& f : forces.pointForces)
    if (pushing(f, t)) wake(f.body, contacts);
}

bool Sleep::wakeTouched(const std::vector<Contact>& found, std::vector<Contact>& contacts) {
  if (sleeping_ == 0) return false;
  bool woke = false;
  for (const Contact& c : found)
    for (int body : {c.a, c.b})
      if (asleep(body)) wake(body, contacts), woke = true;
  return woke;
}

}  // namespace sim::world

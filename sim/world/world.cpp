#include "sim/world/world.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "sim/collision/compound.h"
#include "sim/collision/quad_pairs.h"
#include "sim/world/method_models.h"
#include "sim/world/worker_pool.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

Diverged::Diverged(double t, int b)
    : std::runtime_error("state is no longer finite at t = " + std::to_string(t)), time(t), body(b) {}

ImpactsPileUp::ImpactsPileUp(double t, int n)
    : std::runtime_error("more than " + std::to_string(n) + " impacts in one step at t = " + std::to_string(t) +
                         ": impacts pile up; use --collisions sequential"),
      time(t) {}

InitialOverlap::InitialOverlap(int a_, int b_, double d)
    : std::runtime_error("bodies overlap at the start"), a(a_), b(b_), depth(d) {}

void World::applyImpulse(int i, const Vec2& r, const Vec2& j) {
  Body& b = bodies[i];
  b.v += b.invMass * j;
  b.omega += b.invInertia * cross(r - b.x, j);
}

void World::rates(double t, const States& y, Rates& out) const {
  // forces and torques: the applied forces on at t, and what the method's contacts push with
  forces.accumulate(t, bodies, y, force_, torque_);
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
  (void)collectContacts(margin, found, false, false);
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
  contactPairsKept_ = collectContacts(margin, found, skip, true, threads, skip ? nullptr : &contacts, sideSlack);
  // sleeping islands that an awake body touches wake before the solve (Box2D v3 wakes a solver set
  // when a contact begins touching it), and their own contacts are found with them (and may touch
  // another island)
  while (skip && sleep_.wakeTouched(found, contacts))
    (void)collectContacts(margin, found, sleep_.sleepingBodies() > 0, true, threads, nullptr, sideSlack);
}

void World::makeProxies() const {
  proxies_.clear();
  proxiesFor_ = bodies.size();
  const bool parts = std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.shape.kind == ShapeKind::Compound; });
  if (!parts) return;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i)
    for (int k = 0; k < partCount(bodies[i].shape); ++k) proxies_.push_back({i, k});
}

// collectContacts' stages over one call: its options, and the proxies, pairs and manifolds it
// writes into the world's scratch (World's mutable members); defined here, in one class, so that
// each stage inlines into the loop that calls it as the lambdas it replaces did
class World::ContactPass {
 public:
  ContactPass(const World& world, double margin, double sideSlack, bool awakeOnly, bool warmStart)
      : w_(world),
        margin_(margin),
        sideSlack_(sideSlack),
        awakeOnly_(awakeOnly),
        warmStart_(warmStart),
        hasParts_(!world.proxies_.empty()),
        n_(hasParts_ ? static_cast<int>(world.proxies_.size()) : static_cast<int>(world.bodies.size())) {}

  // each proxy placed once (one sine and cosine, its vertices in the world), for its bounds and
  // every pair it is in; shared between `threads` when given
  void placeProxies(WorkerPool* threads) const {
    w_.placed_.resize(n_);
    w_.boxes_.resize(n_);
    if (!threads) return placeRange(0, n_);
    threads->run([&](int t) {
      const auto [first, last] = Share{t, threads->size()}.of(0, n_);
      placeRange(first, last);
    });
  }

  // the broad phase's candidate pairs (pair_cache.h), less those of one body's parts: they never
  // collide with each other
  void findPairs() const {
    w_.fixed_.resize(n_);
    for (int i = 0; i < n_; ++i) w_.fixed_[i] = w_.bodies[bodyOf(i)].isStatic;
    w_.pairCache_.find(w_.boxes_, w_.fixed_, w_.pairs_);
    if (hasParts_) std::erase_if(w_.pairs_, [&](const std::pair<int, int>& p) { return bodyOf(p.first) == bodyOf(p.second); });
  }

  // soft_step's contact recycling (contact_recycle.h): each pair's manifold as made, kept by pair;
  // while the candidate pairs are last call's (a pile at rest), in place, else merged by pair into
  // a list for this call's pairs
  void startRecycling() {
    if (w_.recycleReady_) {
      std::swap(w_.recycle_, w_.recycleNext_);
      w_.recycleReady_ = false;
    }
    recycling_ = w_.recycleDistance > 0.0 && w_.collisions == CollisionMethod::SoftStep && warmStart_;
    if (!recycling_) {
      // (a solver's call without recycling; a look at the contacts, findContacts(margin), leaves
      // the count of the solver's last call as it was)
      if (warmStart_) w_.recycledNow_.clear();
      return;
    }
    const std::vector<std::pair<int, int>>& pairs = w_.pairs_;
    w_.recycledNow_.assign(pairs.size(), 0);
    // (each proxy's reach, once: its shape is fixed)
    if (w_.extent_.size() != static_cast<size_t>(n_)) {
      w_.extent_.resize(n_);
      for (int i = 0; i < n_; ++i) w_.extent_[i] = w_.fixed_[i] ? 0.0 : boundingRadius(*w_.placed_[i].shape);
    }
    w_.keysNow_.resize(pairs.size());
    for (size_t k = 0; k < pairs.size(); ++k) w_.keysNow_[k] = keyBits(pairs[k]);
    inPlace_ = w_.keysNow_ == w_.recycleKeys_ && w_.recycle_.size() == pairs.size();
    if (!inPlace_) {
      w_.recycleNext_.resize(pairs.size());
      w_.recycleReady_ = true;
      std::swap(w_.recycleKeys_, w_.keysNow_);
    }
  }

  // one thread: a chunk of pairs at a time, written over the entries kept from the last call (fill
  // writes every field), so that a step does not clear 208 bytes per contact first. While each
  // touching pair is the one `lastStep` holds at its place (a pile that keeps its contacts), its
  // contact is written over its own, warm started from itself: a pass over one list, not two (a
  // third of collectContacts' time on the 5,050-box pyramid); at the first that is not, the list so
  // far goes to `found` and the rest is written there
  bool collideInOrder(std::vector<Contact>& found, std::vector<Contact>* lastStep) const {
    const int pairCount = static_cast<int>(w_.pairs_.size());
    constexpr int kChunk = 4 * kQuadLanes;
    Manifold chunk[kChunk];
    size_t next = 0, old = 0;
    bool over = lastStep && warmStart_;
    for (int first = 0; first < pairCount; first += kChunk) {
      const int last = std::min(first + kChunk, pairCount);
      collideRange(first, last, chunk);
      for (int k = first; k < last; ++k) {
        if (chunk[k - first].count == 0) continue;
        if (over) {
          if (overwriteAt(*lastStep, next, w_.pairs_[k], chunk[k - first])) continue;
          found.assign(lastStep->begin(), lastStep->begin() + static_cast<std::ptrdiff_t>(next));
          old = next, over = false;
        }
        if (next == found.size()) found.emplace_back();
        fill(found[next++], w_.pairs_[k], chunk[k - first], old);
      }
    }
    if (!over) {
      found.resize(next);
      return false;
    }
    const bool kept = next == lastStep->size();
    lastStep->resize(next);
    std::swap(found, *lastStep);
    return kept;
  }

  // threads: each collides its share of the pairs and counts the touching ones (touching_[t + 1]),
  // then touching_[t] is where thread t's touching pairs begin in the list
  void collideShares(WorkerPool& threads) const {
    const int parts = threads.size(), pairCount = static_cast<int>(w_.pairs_.size());
    w_.manifolds_.resize(pairCount);
    w_.touching_.assign(parts + 1, 0);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      collideRange(first, last, w_.manifolds_.data() + first);
      for (int k = first; k < last; ++k) w_.touching_[t + 1] += w_.manifolds_[k].count > 0;
    });
    for (int t = 0; t < parts; ++t) w_.touching_[t + 1] += w_.touching_[t];
  }

  // as many touching pairs as last step: when each is the pair last step's list holds at its place
  // (each thread checks its share), every contact is written over its own, as on one thread;
  // whether they were
  bool overwriteShares(WorkerPool& threads, std::vector<Contact>* lastStep) const {
    const int parts = threads.size(), pairCount = static_cast<int>(w_.pairs_.size());
    if (!lastStep || !warmStart_ || static_cast<size_t>(w_.touching_[parts]) != lastStep->size()) return false;
    std::vector<char>& differs = w_.differs_;
    // (one task: the threads meet after checking, and all read the same verdict)
    differs.assign(parts, 0);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      int next = w_.touching_[t];
      for (int k = first; k < last && !differs[t]; ++k)
        if (w_.manifolds_[k].count > 0) differs[t] = !samePair((*lastStep)[next++], w_.pairs_[k]);
      threads.sync();
      if (std::find(differs.begin(), differs.end(), 1) != differs.end()) return;
      next = w_.touching_[t];
      for (int k = first; k < last; ++k)
        if (w_.manifolds_[k].count > 0) overwrite((*lastStep)[next++], w_.manifolds_[k]);
    });
    return std::find(differs.begin(), differs.end(), 1) == differs.end();
  }

  // threads: each writes its touching pairs into `found` from where the shares before it end (the
  // same list, in order; the entries kept from the last call are overwritten whole by fill)
  void fillShares(WorkerPool& threads, std::vector<Contact>& found) const {
    const int parts = threads.size(), pairCount = static_cast<int>(w_.pairs_.size());
    found.resize(w_.touching_[parts]);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      int next = w_.touching_[t];
      size_t old = first < last && warmStart_ ? from(w_.pairs_[first]) : 0;
      for (int k = first; k < last; ++k)
        if (w_.manifolds_[k].count > 0) fill(found[next++], w_.pairs_[k], w_.manifolds_[k], old);
    });
  }

 private:
  // how many entries ahead recycleRange brings in
  static constexpr size_t kRecycleAhead = 4;
  // how many contacts ahead collideInOrder brings in
  static constexpr size_t kContactsAhead = 8;

  // a proxy's body and part (while every body is one shape, proxy i is body i, part 0)
  int bodyOf(int i) const { return hasParts_ ? w_.proxies_[i].body : i; }
  int partOf(int i) const { return hasParts_ ? w_.proxies_[i].part : 0; }
  // a proxy pair as a contact's pairKey
  std::tuple<int, int, int, int> keyOf(const std::pair<int, int>& p) const {
    return {bodyOf(p.first), partOf(p.first), bodyOf(p.second), partOf(p.second)};
  }
  // a proxy pair as the recycled entries' key
  static std::uint64_t keyBits(const std::pair<int, int>& p) {
    return static_cast<std::uint64_t>(p.first) << 32 | static_cast<std::uint32_t>(p.second);
  }
  // the cache lines of *p brought in ahead of their use (for writing when kWrite)
  template <int kWrite, class T>
  static void prefetch(const T* p) {
    for (size_t line = 0; line < sizeof(T); line += 64) __builtin_prefetch(reinterpret_cast<const char*>(p) + line, kWrite);
  }

  // proxies [first, last) placed, with their bounds grown by the margin
  void placeRange(int first, int last) const {
    for (int i = first; i < last; ++i) {
      const Body& b = w_.bodies[bodyOf(i)];
      const Shape& shape = partShape(b.shape, partOf(i));
      place(shape, partPoseOf(b.shape, partOf(i), b.pose()), w_.placed_[i]);
      Aabb box = bounds(w_.placed_[i]);
      box.lower -= Vec2::Constant(margin_);
      box.upper += Vec2::Constant(margin_);
      w_.boxes_[i] = box;
    }
  }

  // pairs_[k] is of a sleeping pile: not tested, its contacts kept as they were when it fell asleep
  bool skipped(int k) const {
    const int i = bodyOf(w_.pairs_[k].first), j = bodyOf(w_.pairs_[k].second);
    const Sleep& sleep = w_.sleep_;
    return awakeOnly_ && (w_.bodies[i].isStatic || sleep.asleep(i)) && (w_.bodies[j].isStatic || sleep.asleep(j));
  }
  // the manifold of pairs_[k], or none for a skipped pair
  Manifold collidePair(int k) const {
    return skipped(k) ? Manifold{}
                      : collide(w_.placed_[w_.pairs_[k].first], w_.placed_[w_.pairs_[k].second], margin_, sideSlack_);
  }
  // pairs_[k, k + 4) into out[0, 4): four box pairs at once (quad_pairs.h: collide()'s manifolds to
  // the bit), else one at a time
  void collideFour(int k, Manifold* out) const {
    const PlacedShape* a[kQuadLanes];
    const PlacedShape* b[kQuadLanes];
    bool quads = true;
    for (int q = 0; q < kQuadLanes; ++q) {
      a[q] = &w_.placed_[w_.pairs_[k + q].first], b[q] = &w_.placed_[w_.pairs_[k + q].second];
      quads = quads && !skipped(k + q) && isQuadPair(*a[q], *b[q]);
    }
    if (quads) return collideQuadPairs(a, b, margin_, out, sideSlack_);
    for (int q = 0; q < kQuadLanes; ++q) out[q] = collidePair(k + q);
  }
  // the manifolds of pairs_[first, last) into out[0, last − first)
  void collideRange(int first, int last, Manifold* out) const {
    if (recycling_) return recycleRange(first, last, out);
    int k = first;
    for (; k + kQuadLanes <= last; k += kQuadLanes) collideFour(k, out + (k - first));
    for (; k < last; ++k) out[k - first] = collidePair(k);
  }

  // where the merge of last call's recycled entries starts for pairs_[first, ...) (both sorted by
  // pair); in place, the entries are the pairs' own
  size_t recycledFrom(int first, int last) const {
    if (inPlace_ || first >= last) return 0;
    const std::vector<RecycleEntry>& recycle = w_.recycle_;
    return static_cast<size_t>(std::lower_bound(recycle.begin(), recycle.end(), keyBits(w_.pairs_[first]),
                                                [](const RecycleEntry& e, std::uint64_t key) { return e.key < key; }) -
                               recycle.begin());
  }
  // last call's entry of pairs_[k] (key `key`), or none: at k in place, else walked to from `old`
  const RecycleEntry* recycledEntry(int k, std::uint64_t key, size_t& old) const {
    const std::vector<RecycleEntry>& recycle = w_.recycle_;
    if (inPlace_) {
      // (the entries a few ahead brought in while this one is read: 304 bytes each, 4.5 MB on the
      // 5,050-box pyramid, and their first read was the hot spot of recycledManifold)
      if (static_cast<size_t>(k) + kRecycleAhead < recycle.size()) prefetch<0>(&recycle[k + kRecycleAhead]);
      return &recycle[k];
    }
    while (old < recycle.size() && recycle[old].key < key) ++old;
    return old < recycle.size() && recycle[old].key == key ? &recycle[old] : nullptr;
  }
  // pairs_[first, last) into out[0, last − first), each pair that touched keeping its manifold
  // while it moved little (contact_recycle.h), the others collided
  void recycleRange(int first, int last, Manifold* out) const {
    size_t old = recycledFrom(first, last);
    for (int k = first; k < last; ++k) {
      const std::uint64_t key = keyBits(w_.pairs_[k]);
      const RecycleEntry* before = recycledEntry(k, key, old);
      RecycleEntry& entry = inPlace_ ? w_.recycle_[k] : w_.recycleNext_[k];
      const PlacedShape &a = w_.placed_[w_.pairs_[k].first], &b = w_.placed_[w_.pairs_[k].second];
      if (skipped(k)) {
        out[k - first] = Manifold{};
        entry = RecycleEntry{};
        entry.key = key;
        continue;
      }
      if (before) {
        const double extent = std::max(w_.extent_[w_.pairs_[k].first], w_.extent_[w_.pairs_[k].second]);
        if (recycledManifold(*before, a.pose, b.pose, extent, w_.recycleDistance, out[k - first])) {
          if (!inPlace_) entry = *before;
          w_.recycledNow_[k] = 1;
          continue;
        }
      }
      out[k - first] = collide(a, b, margin_, sideSlack_);
      entry = recycleEntry(key, a.pose, b.pose, out[k - first]);
    }
  }

  // a contact written whole, its impulses those of last step's contact of the same pair (`old`
  // walks `contacts`, sorted by pair as the pairs are, from `from`), matched while it is at hand
  void fill(Contact& c, const std::pair<int, int>& pair, const Manifold& m, size_t& old) const {
    const int i = bodyOf(pair.first), j = bodyOf(pair.second);
    c.a = i, c.b = j;
    c.partA = partOf(pair.first), c.partB = partOf(pair.second);
    c.manifold = m;
    c.restitution = combinedRestitution(w_.bodies[i].restitution, w_.bodies[j].restitution);
    c.friction = combinedFriction(w_.bodies[i], w_.bodies[j]);
    c.state[0] = c.state[1] = ContactPointState{};
    if (!warmStart_) return;
    const std::vector<Contact>& contacts = w_.contacts;
    const auto key = keyOf(pair);
    while (old < contacts.size() && pairKey(contacts[old]) < key) ++old;
    if (old < contacts.size() && pairKey(contacts[old]) == key) carryImpulses(contacts[old], c);
  }
  // where last step's contacts reach a pair
  size_t from(const std::pair<int, int>& pair) const {
    const std::vector<Contact>& contacts = w_.contacts;
    return static_cast<size_t>(
        std::lower_bound(contacts.begin(), contacts.end(), keyOf(pair),
                         [](const Contact& c, const std::tuple<int, int, int, int>& key) { return pairKey(c) < key; }) -
        contacts.begin());
  }
  // whether a contact is of the proxy pair `pair`
  bool samePair(const Contact& c, const std::pair<int, int>& pair) const {
    return c.a == bodyOf(pair.first) && c.b == bodyOf(pair.second) && c.partA == partOf(pair.first) &&
           c.partB == partOf(pair.second);
  }
  // the same pair's contact last step, written over with its new manifold and warm started from
  // itself (its bodies, so its restitution and friction, are the ones it had: a body's
  // coefficients are fixed from the start of a run)
  static void overwrite(Contact& c, const Manifold& m) {
    const CarriedPoints previous = carriedPoints(c);
    c.manifold = m;
    c.state[0] = c.state[1] = ContactPointState{};
    carryImpulses(previous, c);
  }
  // lastStep[next] written over with `pair`'s manifold when it is that pair's contact (then next
  // moves on); whether it was
  bool overwriteAt(std::vector<Contact>& lastStep, size_t& next, const std::pair<int, int>& pair, const Manifold& m) const {
    Contact* c = next < lastStep.size() ? &lastStep[next] : nullptr;
    // (the contacts a few ahead brought in while this one is written: the list is 3 MB on the
    // 5,050-box pyramid, read once a step)
    if (next + kContactsAhead < lastStep.size()) prefetch<1>(&lastStep[next + kContactsAhead]);
    if (!c || !samePair(*c, pair)) return false;
    overwrite(*c, m);
    ++next;
    return true;
  }

  const World& w_;
  const double margin_, sideSlack_;
  const bool awakeOnly_, warmStart_;
  const bool hasParts_;  // some body is of parts: proxies_ says each proxy's body and part
  const int n_;          // proxies
  bool recycling_ = false, inPlace_ = false;
};

bool World::collectContacts(double margin, std::vector<Contact>& found, bool awakeOnly, bool warmStart, WorkerPool* threads,
                            std::vector<Contact>* lastStep, double sideSlack) const {
  // (a body's shape is fixed from its making: only bodies added since ask for new proxies)
  if (proxiesFor_ != bodies.size()) makeProxies();
  ContactPass pass(*this, margin, sideSlack, awakeOnly, warmStart);
  WorkerPool* const shared = threads && threads->size() > 1 ? threads : nullptr;
  // the proxies where they are, and the broad phase's pairs of them
  pass.placeProxies(shared);
  pass.findPairs();
  // soft_step: which pairs may keep last call's manifold
  pass.startRecycling();
  // the narrow phase, each touching pair's contact written over its own last step's where it can
  if (!shared) return pass.collideInOrder(found, lastStep);
  pass.collideShares(*shared);
  if (pass.overwriteShares(*shared, lastStep)) {
    std::swap(found, *lastStep);
    return true;
  }
  pass.fillShares(*shared, found);
  return false;
}

long World::recycledContacts() const { return std::count(recycledNow_.begin(), recycledNow_.end(), 1); }

void World::start() {
  if (started_) return;
  timeline_ = Timeline<ImpulseEvent>(dt, events, forces.breakpoints());
  measureScene();
  if (collisions == CollisionMethod::Auto) chooseMethod();
  method_ = OwnedMethod(makeMethod(collisions, precision));
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
  const bool loaded = forces.gravity != Vec2::Zero() || !forces.gravityOnly();
  unsigned needs = 0;
  if (dynamic > 0 && bodies.size() >= 2) needs |= bit(Phenomenon::IsolatedImpacts);
  // bodies that touch at the start under a load rest on each other: their contacts persist
  if (needs && loaded && !findContacts(settings::kContactMargin).empty()) needs |= bit(Phenomenon::RestingContact);
  collisions = leastMethodFor(needs);
  if (!needs) methodReason = MethodReason::FewBodies;
  else if (has(needs, Phenomenon::RestingContact)) methodReason = MethodReason::PersistentContacts;
  else methodReason = MethodReason::IsolatedImpacts;
  mayStackUp_ = collisions == CollisionMethod::Event;
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

void World::advanceTo(double tEnd, StepObserver* observer) {
  start();
  timeline_.advanceTo(*this, tEnd, observer);
}

void World::advanceWithin(double t, double tEnd, StepObserver* observer) {
  start();
  timeline_.advanceWithin(*this, t, tEnd, observer);
}

// the timeline's step (timeline.h): one step of size h by the collision method (methods.h), and
// what is the world's around it: sleeping, `auto`'s switch and the finiteness check. Under
// `auto`, when the event method finds impacts piling up (a stack or a pile forming), the step is
// done again from where it began by the stack solver, which goes on from there.
void World::step(double stop, double end) {
  const double h = stop - time;
  const TimeStep thisStep{time, h};
  // a point force on during the step wakes the island it pushes
  if (sleeping()) sleep_.wakeForced(forces, thisStep.midpoint(), contacts);
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
  if (sleeping()) sleep_.afterStep(bodies, contacts, forces, thisStep.midpoint(), h);
  // stop at the first non-finite state rather than carry NaN forward
  checkFinite(time + h);
  time = end;
}

// the stack solver from why.time on: the start of the step in which the impacts piled up, or the
// end of the one in which a contact persisted
void World::switchToStackSolver(const MethodSwitch& why) {
  collisions = CollisionMethod::Sequential;
  methodReason = why.a < 0 ? MethodReason::StackFormed : MethodReason::ContactPersisted;
  methodSwitch = why;
  mayStackUp_ = false;
  contacts.clear();
  method_ = OwnedMethod(makeMethod(collisions, precision));
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
  return sleep && (collisions == CollisionMethod::Sequential || collisions == CollisionMethod::SoftStep);
}

void World::checkFinite(double t) const {
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    if (!isFinite(b.x) || !std::isfinite(b.angle) || !isFinite(b.v) || !std::isfinite(b.omega))
      throw Diverged(t, static_cast<int>(i));
  }
}

}  // namespace sim::world

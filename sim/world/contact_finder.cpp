#include "sim/world/contact_finder.h"

#include <algorithm>
#include <tuple>

#include "sim/collision/compound.h"
#include "sim/collision/quad_pairs.h"
#include "sim/world/worker_pool.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

void ContactFinder::makeProxies(const std::vector<Body>& bodies) {
  proxies_.clear();
  proxiesFor_ = bodies.size();
  const bool parts = std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.shape.kind == ShapeKind::Compound; });
  if (!parts) return;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i)
    for (int k = 0; k < partCount(bodies[i].shape); ++k) proxies_.push_back({i, k});
}

// collect's stages over one call: its query, and the proxies, pairs and manifolds it writes into
// the finder's scratch; one class, so that each stage inlines into the loop that calls it
class ContactFinder::Pass {
 public:
  Pass(ContactFinder& finder, const ContactQuery& query)
      : f_(finder),
        bodies_(query.bodies),
        sleep_(query.sleep),
        last_(query.last),
        margin_(query.margin),
        sideSlack_(query.sideSlack),
        recycleDistance_(query.recycleDistance),
        awakeOnly_(query.awakeOnly),
        warmStart_(query.warmStart),
        hasParts_(!finder.proxies_.empty()),
        n_(hasParts_ ? static_cast<int>(finder.proxies_.size()) : static_cast<int>(query.bodies.size())) {}

  // each proxy placed once (one sine and cosine, its vertices in the world), for its bounds and
  // every pair it is in; shared between `threads` when given
  void placeProxies(WorkerPool* threads) const {
    f_.placed_.resize(n_);
    f_.boxes_.resize(n_);
    if (!threads) return placeRange(0, n_);
    threads->run([&](int t) {
      const auto [first, last] = Share{t, threads->size()}.of(0, n_);
      placeRange(first, last);
    });
  }

  // the broad phase's candidate pairs (pair_cache.h), less those of one body's parts: they never
  // collide with each other
  void findPairs() const {
    f_.fixed_.resize(n_);
    for (int i = 0; i < n_; ++i) f_.fixed_[i] = bodies_[bodyOf(i)].isStatic;
    f_.pairCache_.find(f_.boxes_, f_.fixed_, f_.pairs_);
    if (hasParts_) std::erase_if(f_.pairs_, [&](const std::pair<int, int>& p) { return bodyOf(p.first) == bodyOf(p.second); });
  }

  // soft_step's contact recycling (contact_recycle.h): each pair's manifold as made, kept by pair;
  // while the candidate pairs are last call's (a pile at rest), in place, else merged by pair into
  // a list for this call's pairs
  void startRecycling() {
    if (f_.recycleReady_) {
      std::swap(f_.recycle_, f_.recycleNext_);
      f_.recycleReady_ = false;
    }
    recycling_ = recycleDistance_ > 0.0 && warmStart_;
    if (!recycling_) {
      // (a solver's call without recycling; a look at the contacts, findContacts(margin), leaves
      // the count of the solver's last call as it was)
      if (warmStart_) f_.recycledNow_.clear();
      return;
    }
    const std::vector<std::pair<int, int>>& pairs = f_.pairs_;
    f_.recycledNow_.assign(pairs.size(), 0);
    // (each proxy's reach, once: its shape is fixed)
    if (f_.extent_.size() != static_cast<size_t>(n_)) {
      f_.extent_.resize(n_);
      for (int i = 0; i < n_; ++i) f_.extent_[i] = f_.fixed_[i] ? 0.0 : boundingRadius(*f_.placed_[i].shape);
    }
    f_.keysNow_.resize(pairs.size());
    for (size_t k = 0; k < pairs.size(); ++k) f_.keysNow_[k] = keyBits(pairs[k]);
    inPlace_ = f_.keysNow_ == f_.recycleKeys_ && f_.recycle_.size() == pairs.size();
    if (!inPlace_) {
      f_.recycleNext_.resize(pairs.size());
      f_.recycleReady_ = true;
      std::swap(f_.recycleKeys_, f_.keysNow_);
    }
  }

  // one thread: a chunk of pairs at a time, written over the entries kept from the last call (fill
  // writes every field), so that a step does not clear 208 bytes per contact first. While each
  // touching pair is the one `lastStep` holds at its place (a pile that keeps its contacts), its
  // contact is written over its own, warm started from itself: a pass over one list, not two (a
  // third of the finder's time on the 5,050-box pyramid); at the first that is not, the list so
  // far goes to `found` and the rest is written there
  bool collideInOrder(std::vector<Contact>& found, std::vector<Contact>* lastStep) const {
    const int pairCount = static_cast<int>(f_.pairs_.size());
    constexpr int kChunk = 4 * kQuadLanes;
    Manifold chunk[kChunk];
    size_t next = 0, old = 0;
    bool over = lastStep && warmStart_;
    for (int start = 0; start < pairCount; start += kChunk) {
      const int last = std::min(start + kChunk, pairCount);
      // (while each pair recycles into its own contact, the chunk waits for the first that does not)
      const int first = over && recycling_ && inPlace_ ? recycledInPlace(start, last, *lastStep, next) : start;
      if (first == last) continue;
      collideRange(first, last, chunk);
      for (int k = first; k < last; ++k) {
        if (chunk[k - first].count == 0) continue;
        if (over) {
          if (overwriteAt(*lastStep, next, f_.pairs_[k], chunk[k - first])) continue;
          found.assign(lastStep->begin(), lastStep->begin() + static_cast<std::ptrdiff_t>(next));
          old = next, over = false;
        }
        if (next == found.size()) found.emplace_back();
        fill(found[next++], f_.pairs_[k], chunk[k - first], old);
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
    const int parts = threads.size(), pairCount = static_cast<int>(f_.pairs_.size());
    f_.manifolds_.resize(pairCount);
    f_.touching_.assign(parts + 1, 0);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      collideRange(first, last, f_.manifolds_.data() + first);
      for (int k = first; k < last; ++k) f_.touching_[t + 1] += f_.manifolds_[k].count > 0;
    });
    for (int t = 0; t < parts; ++t) f_.touching_[t + 1] += f_.touching_[t];
  }

  // as many touching pairs as last step: when each is the pair last step's list holds at its place
  // (each thread checks its share), every contact is written over its own, as on one thread;
  // whether they were
  bool overwriteShares(WorkerPool& threads, std::vector<Contact>* lastStep) const {
    const int parts = threads.size(), pairCount = static_cast<int>(f_.pairs_.size());
    if (!lastStep || !warmStart_ || static_cast<size_t>(f_.touching_[parts]) != lastStep->size()) return false;
    std::vector<char>& differs = f_.differs_;
    // (one task: the threads meet after checking, and all read the same verdict)
    differs.assign(parts, 0);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      int next = f_.touching_[t];
      for (int k = first; k < last && !differs[t]; ++k)
        if (f_.manifolds_[k].count > 0) differs[t] = !samePair((*lastStep)[next++], f_.pairs_[k]);
      threads.sync();
      if (std::find(differs.begin(), differs.end(), 1) != differs.end()) return;
      next = f_.touching_[t];
      for (int k = first; k < last; ++k)
        if (f_.manifolds_[k].count > 0) overwrite((*lastStep)[next++], f_.manifolds_[k]);
    });
    return std::find(differs.begin(), differs.end(), 1) == differs.end();
  }

  // threads: each writes its touching pairs into `found` from where the shares before it end (the
  // same list, in order; the entries kept from the last call are overwritten whole by fill)
  void fillShares(WorkerPool& threads, std::vector<Contact>& found) const {
    const int parts = threads.size(), pairCount = static_cast<int>(f_.pairs_.size());
    found.resize(f_.touching_[parts]);
    threads.run([&](int t) {
      const auto [first, last] = Share{t, parts}.of(0, pairCount);
      int next = f_.touching_[t];
      size_t old = first < last && warmStart_ ? from(f_.pairs_[first]) : 0;
      for (int k = first; k < last; ++k)
        if (f_.manifolds_[k].count > 0) fill(found[next++], f_.pairs_[k], f_.manifolds_[k], old);
    });
  }

 private:
  // how many entries ahead recycleRange brings in
  static constexpr size_t kRecycleAhead = 4;
  // how many contacts ahead collideInOrder brings in
  static constexpr size_t kContactsAhead = 8;

  // a proxy's body and part (while every body is one shape, proxy i is body i, part 0)
  int bodyOf(int i) const { return hasParts_ ? f_.proxies_[i].body : i; }
  int partOf(int i) const { return hasParts_ ? f_.proxies_[i].part : 0; }
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
      const Body& b = bodies_[bodyOf(i)];
      const Shape& shape = partShape(b.shape, partOf(i));
      place(shape, partPoseOf(b.shape, partOf(i), b.pose()), f_.placed_[i]);
      Aabb box = bounds(f_.placed_[i]);
      box.lower -= Vec2::Constant(margin_);
      box.upper += Vec2::Constant(margin_);
      f_.boxes_[i] = box;
    }
  }

  // pairs_[k] is of a sleeping pile: not tested, its contacts kept as they were when it fell asleep
  bool skipped(int k) const {
    const int i = bodyOf(f_.pairs_[k].first), j = bodyOf(f_.pairs_[k].second);
    const Sleep& sleep = sleep_;
    return awakeOnly_ && (bodies_[i].isStatic || sleep.asleep(i)) && (bodies_[j].isStatic || sleep.asleep(j));
  }
  // the manifold of pairs_[k], or none for a skipped pair
  Manifold collidePair(int k) const {
    return skipped(k) ? Manifold{}
                      : collide(f_.placed_[f_.pairs_[k].first], f_.placed_[f_.pairs_[k].second], margin_, sideSlack_);
  }
  // pairs_[k, k + 4) into out[0, 4): four box pairs at once (quad_pairs.h: collide()'s manifolds to
  // the bit), else one at a time
  void collideFour(int k, Manifold* out) const {
    const PlacedShape* a[kQuadLanes];
    const PlacedShape* b[kQuadLanes];
    bool quads = true;
    for (int q = 0; q < kQuadLanes; ++q) {
      a[q] = &f_.placed_[f_.pairs_[k + q].first], b[q] = &f_.placed_[f_.pairs_[k + q].second];
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
    const std::vector<RecycleEntry>& recycle = f_.recycle_;
    return static_cast<size_t>(std::lower_bound(recycle.begin(), recycle.end(), keyBits(f_.pairs_[first]),
                                                [](const RecycleEntry& e, std::uint64_t key) { return e.key < key; }) -
                               recycle.begin());
  }
  // last call's entry of pairs_[k] (key `key`), or none: at k in place, else walked to from `old`
  const RecycleEntry* recycledEntry(int k, std::uint64_t key, size_t& old) const {
    const std::vector<RecycleEntry>& recycle = f_.recycle_;
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
      const std::uint64_t key = keyBits(f_.pairs_[k]);
      const RecycleEntry* before = recycledEntry(k, key, old);
      RecycleEntry& entry = inPlace_ ? f_.recycle_[k] : f_.recycleNext_[k];
      const PlacedShape &a = f_.placed_[f_.pairs_[k].first], &b = f_.placed_[f_.pairs_[k].second];
      if (skipped(k)) {
        out[k - first] = Manifold{};
        entry = RecycleEntry{};
        entry.key = key;
        continue;
      }
      if (before) {
        const double extent = std::max(f_.extent_[f_.pairs_[k].first], f_.extent_[f_.pairs_[k].second]);
        if (recycledManifold(*before, a.pose, b.pose, extent, recycleDistance_, out[k - first])) {
          if (!inPlace_) entry = *before;
          f_.recycledNow_[k] = 1;
          continue;
        }
      }
      out[k - first] = collide(a, b, margin_, sideSlack_);
      entry = recycleEntry(key, a.pose, b.pose, out[k - first]);
    }
  }

  // pairs_[first, last) recycled each into last step's contact at `next` while that is the pair's
  // and was made from its entry (in place: last call's pairs): only the points move, and their
  // impulses stay with them, as overwrite's carry would keep them; where the first pair that did not
  // is (last when all did)
  int recycledInPlace(int first, int last, std::vector<Contact>& lastStep, size_t& next) const {
    int k = first;
    for (; k < last && next < lastStep.size(); ++k) {
      Contact& c = lastStep[next];
      if (next + kContactsAhead < lastStep.size()) prefetch<1>(&lastStep[next + kContactsAhead]);
      if (static_cast<size_t>(k) + kRecycleAhead < f_.recycle_.size()) prefetch<0>(&f_.recycle_[k + kRecycleAhead]);
      const RecycleEntry& entry = f_.recycle_[k];
      if (!samePair(c, f_.pairs_[k]) || skipped(k) || !madeFrom(entry, c.manifold)) break;
      const int i = f_.pairs_[k].first, j = f_.pairs_[k].second;
      const double extent = std::max(f_.extent_[i], f_.extent_[j]);
      if (!recycledPointsInto(entry, f_.placed_[i].pose, f_.placed_[j].pose, extent, recycleDistance_, c.manifold)) break;
      // (the state of a point the manifold lacks, as overwrite leaves it)
      for (int p = c.manifold.count; p < 2; ++p) c.state[p] = ContactPointState{};
      f_.recycledNow_[k] = 1;
      ++next;
    }
    return k;
  }

  // a contact written whole, its impulses those of last step's contact of the same pair (`old`
  // walks the query's `last`, sorted by pair as the pairs are, from `from`), matched while it is at hand
  void fill(Contact& c, const std::pair<int, int>& pair, const Manifold& m, size_t& old) const {
    const int i = bodyOf(pair.first), j = bodyOf(pair.second);
    c.a = i, c.b = j;
    c.partA = partOf(pair.first), c.partB = partOf(pair.second);
    c.manifold = m;
    c.restitution = combinedRestitution(bodies_[i].restitution, bodies_[j].restitution);
    c.friction = combinedFriction(bodies_[i], bodies_[j]);
    c.state[0] = c.state[1] = ContactPointState{};
    if (!warmStart_) return;
    const std::vector<Contact>& contacts = last_;
    const auto key = keyOf(pair);
    while (old < contacts.size() && pairKey(contacts[old]) < key) ++old;
    if (old < contacts.size() && pairKey(contacts[old]) == key) carryImpulses(contacts[old], c);
  }
  // where last step's contacts reach a pair
  size_t from(const std::pair<int, int>& pair) const {
    const std::vector<Contact>& contacts = last_;
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

  ContactFinder& f_;
  const std::vector<Body>& bodies_;
  const Sleep& sleep_;
  const std::vector<Contact>& last_;
  const double margin_, sideSlack_, recycleDistance_;
  const bool awakeOnly_, warmStart_;
  const bool hasParts_;  // some body is of parts: proxies_ says each proxy's body and part
  const int n_;          // proxies
  bool recycling_ = false, inPlace_ = false;
};

bool ContactFinder::collect(const ContactQuery& query, std::vector<Contact>& found, WorkerPool* threads,
                            std::vector<Contact>* lastStep) {
  // (a body's shape is fixed from its making: only bodies added since ask for new proxies)
  if (proxiesFor_ != query.bodies.size()) makeProxies(query.bodies);
  Pass pass(*this, query);
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

long ContactFinder::recycled() const { return std::count(recycledNow_.begin(), recycledNow_.end(), 1); }

}  // namespace sim::world

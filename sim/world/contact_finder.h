// The contacts' upkeep, a unit of its own that the world's methods call through World::findContacts:
// the collision proxies (one per convex shape), the broad phase's pairs of them (pair_cache.h),
// each pair's manifold (collide.h, four box pairs at once: quad_pairs.h), soft_step's recycled
// manifolds (contact_recycle.h) and the warm start from last step's same pair (Catto 2006). From
// one call to the next it keeps scratch, which changes nothing it finds, and soft_step's recycled
// manifolds, which are what recycling finds.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sim/collision/collide.h"
#include "sim/collision/pair_cache.h"
#include "sim/core/body.h"
#include "sim/world/contact.h"
#include "sim/world/contact_recycle.h"
#include "sim/world/sleep.h"

namespace sim::world {
class WorkerPool;

// what one pass over the bodies asks for
struct ContactQuery {
  const std::vector<sim::core::Body>& bodies;
  const Sleep& sleep;
  // last step's contacts, sorted by pair: where the warm start reads each pair's impulses
  const std::vector<Contact>& last;
  double margin = 0.0;     // pairs closer than this, m
  double sideSlack = 0.0;  // the polygon pairs' clipping slack (collide())
  // soft_step's recycling: a touching pair keeps its manifold while it moved less than this, m; 0: off
  double recycleDistance = 0.0;
  bool awakeOnly = false;  // without the pairs of sleeping bodies with each other and with static ones
  bool warmStart = false;  // each point starts from the impulses of `last`'s same pair and features
};

class ContactFinder {
 public:
  // the manifolds into `found` (its entries overwritten, its storage kept); the placing and the
  // narrow phase split between `threads` when there are two or more. `lastStep` (the list `last`
  // is, or none): a list the contacts may be written over while its pairs are theirs (then its
  // storage and found's swap). Returns whether the pairs were lastStep's, each written over its own.
  bool collect(const ContactQuery& query, std::vector<Contact>& found, WorkerPool* threads = nullptr,
               std::vector<Contact>* lastStep = nullptr);
  // how many of the last warm-started call's touching pairs kept their manifold
  long recycled() const;

 private:
  // collect's stages (contact_finder.cpp)
  class Pass;
  void makeProxies(const std::vector<sim::core::Body>& bodies);

  // the collision proxies, one per convex shape, body by body (a body of parts has one per part):
  // empty while every body is one shape, when proxy i is body i
  struct Proxy {
    int body = 0, part = 0;
  };
  std::vector<Proxy> proxies_;
  size_t proxiesFor_ = 0;  // the body count they were made for
  // the broad phase's candidate pairs, kept from one call to the next (the pairs found do not
  // depend on them)
  sim::collision::PairCache pairCache_;
  // soft_step's contact recycling: each candidate pair's manifold as made, by the index of its pair
  // (recycle_, for the pairs recycleKeys_), and the list of this call's pairs when they are others
  // (recycleNext_, swapped in at the next call); which pairs kept theirs; each proxy's reach
  std::vector<RecycleEntry> recycle_, recycleNext_;
  std::vector<std::uint64_t> recycleKeys_, keysNow_;
  std::vector<char> recycledNow_;
  std::vector<double> extent_;
  bool recycleReady_ = false;
  std::vector<std::pair<int, int>> pairs_;           // scratch: the proxies' pairs,
  std::vector<sim::collision::PlacedShape> placed_;  // and the proxies' shapes where they are,
  std::vector<sim::collision::Aabb> boxes_;          // their bounds with the margin,
  std::vector<bool> fixed_;                          // which are static,
  std::vector<sim::collision::Manifold> manifolds_;  // and each pair's manifold, when threads share them,
  std::vector<int> touching_;                        // with where each thread's touching pairs begin,
  std::vector<char> differs_;                        // and whether its pairs differ from last step's
};

}  // namespace sim::world

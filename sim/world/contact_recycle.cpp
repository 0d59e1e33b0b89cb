#include "sim/world/contact_recycle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/core/settings.h"

namespace sim::world {
using sim::collision::Manifold;
using namespace sim::core;

namespace {

// B's pose in A's frame
Pose relativePose(const Pose& a, const Pose& b) {
  const Rot inverse{a.q.c, -a.q.s};
  return {a.toBody(b.x), inverse.then(b.q)};
}

// cos of the angle turned from `then` to `now`
double turnedCos(const Rot& now, const Rot& then) { return now.c * then.c + now.s * then.s; }

// `now` after `then`⁻¹: the turn since
Rot turnSince(const Rot& now, const Rot& then) { return now.then({then.c, -then.s}); }

}  // namespace

RecycleEntry recycleEntry(std::uint64_t key, const Pose& a, const Pose& b, const Manifold& m) {
  RecycleEntry e;
  e.key = key;
  e.valid = m.count > 0;
  e.qA = a.q, e.qB = b.q;
  e.relative = relativePose(a, b);
  for (int k = 0; k < m.count; ++k) {
    e.anchorA[k] = m.points[k].point - a.x;
    e.anchorB[k] = m.points[k].point - b.x;
    e.baseSeparation[k] = m.points[k].separation;
  }
  e.manifold = m;
  return e;
}

namespace {

// whether B moved little enough relative to A since `e` was made for its manifold to be carried
bool recycles(const RecycleEntry& e, const Pose& a, const Pose& b, double extent, double distance) {
  if (!e.valid) return false;
  if (std::min(turnedCos(a.q, e.qA), turnedCos(b.q, e.qB)) <= settings::kRecycleCos) return false;
  // how far any point of B moved relative to A: the shift of its origin, and its turn about it
  // (sin θ ≈ θ for the small turns that pass)
  const Pose now = relativePose(a, b);
  const double turned = std::abs(turnSince(now.q, e.relative.q).s);
  const double shift2 = (now.x - e.relative.x).squaredNorm(), reach = extent * turned;
  // (a pair well inside both halves of the bound passes the test below without its square root,
  // whose latency was the hot spot here: the same verdict, the sum at most nine tenths of it, while
  // the bound's square is a normal number: not overflowed, nor rounded among the subnormals)
  const double quarter2 = 0.25 * distance * distance;
  const bool wellInside = std::isnormal(quarter2) && shift2 <= quarter2 && reach <= 0.4 * distance;
  return wellInside || std::sqrt(shift2) + reach < distance;
}

// `m`'s points (as `e`'s) carried with the two shapes to `a` and `b`, and its separation
void carryPoints(const RecycleEntry& e, const Pose& a, const Pose& b, Manifold& m) {
  const Rot dqA = turnSince(a.q, e.qA), dqB = turnSince(b.q, e.qB);
  m.separation = std::numeric_limits<double>::infinity();
  for (int k = 0; k < m.count; ++k) {
    const Vec2 onA = a.x + dqA.apply(e.anchorA[k]), onB = b.x + dqB.apply(e.anchorB[k]);
    // the normal points from B to A: B's point moving along −n opens the gap
    m.points[k].separation = e.baseSeparation[k] - (onB - onA).dot(m.normal);
    m.points[k].point = 0.5 * (onA + onB);
    m.separation = std::min(m.separation, m.points[k].separation);
  }
}

}  // namespace

bool recycledManifold(const RecycleEntry& e, const Pose& a, const Pose& b, double extent, double distance, Manifold& out) {
  if (!recycles(e, a, b, extent, distance)) return false;
  out = e.manifold;
  carryPoints(e, a, b, out);
  return true;
}

bool madeFrom(const RecycleEntry& e, const Manifold& m) {
  const Manifold& made = e.manifold;
  if (!e.valid || m.count != made.count || m.normal != made.normal) return false;
  for (int k = 0; k < m.count; ++k)
    if (m.points[k].id != made.points[k].id) return false;
  return m.count < 2 || m.points[0].id != m.points[1].id;
}

bool recycledPointsInto(const RecycleEntry& e, const Pose& a, const Pose& b, double extent, double distance, Manifold& m) {
  if (!recycles(e, a, b, extent, distance)) return false;
  carryPoints(e, a, b, m);
  return true;
}

}  // namespace sim::world

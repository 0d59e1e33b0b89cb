// Four box pairs at once (quad_pairs.h) against collide() one pair at a time: every field of every
// manifold the same to the bit, over pairs that touch face to face, corner to face and corner to
// corner, overlap, stand apart, tie exactly (equal boxes stacked, rows side by side) and turn.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "sim/collision/quad_pairs.h"
#include "sim/core/settings.h"
#include "sim/core/simd_support.h"

namespace {

using sim::collision::Manifold;
using sim::collision::PlacedShape;
using namespace sim::core;

// the same bits, field by field (the points past count too: they are stored in the contacts)
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(const Manifold& a, const Manifold& b) {
  bool ok = sameBits(a.normal.x(), b.normal.x()) && sameBits(a.normal.y(), b.normal.y()) && a.count == b.count &&
            sameBits(a.separation, b.separation) && a.sat.valid == b.sat.valid && sameBits(a.sat.separation, b.sat.separation) &&
            a.sat.referenceOnA == b.sat.referenceOnA && a.sat.referenceEdge == b.sat.referenceEdge &&
            a.sat.incidentVertex == b.sat.incidentVertex;
  for (int k = 0; k < 2; ++k)
    ok = ok && sameBits(a.points[k].point.x(), b.points[k].point.x()) && sameBits(a.points[k].point.y(), b.points[k].point.y()) &&
         sameBits(a.points[k].separation, b.points[k].separation) && a.points[k].id == b.points[k].id;
  return ok;
}

// a shape and where it is (placed in compare(), once the list no longer moves: a PlacedShape points
// at its Shape)
struct Posed {
  Shape shape;
  Pose pose;
};

std::string describe(const Manifold& m) {
  std::string s = "count " + std::to_string(m.count) + " n (" + std::to_string(m.normal.x()) + ", " +
                  std::to_string(m.normal.y()) + ") sep " + std::to_string(m.separation) + " sat edge " +
                  std::to_string(m.sat.referenceEdge);
  for (int k = 0; k < m.count; ++k) s += " p" + std::to_string(k) + " id " + std::to_string(m.points[k].id);
  return s;
}

// each pair through collideQuadPairs four at a time and through collide(), with the side slack; the
// count of pairs that touch within the margin (so that a test cannot pass on pairs that never meet)
int compare(const std::vector<std::pair<Posed, Posed>>& pairs, double margin, double sideSlack = 0.0) {
  std::vector<PlacedShape> placedA(pairs.size()), placedB(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    sim::collision::place(pairs[i].first.shape, pairs[i].first.pose, placedA[i]);
    sim::collision::place(pairs[i].second.shape, pairs[i].second.pose, placedB[i]);
  }
  int touching = 0;
  for (size_t first = 0; first + sim::collision::kQuadLanes <= pairs.size(); first += sim::collision::kQuadLanes) {
    const PlacedShape* a[sim::collision::kQuadLanes];
    const PlacedShape* b[sim::collision::kQuadLanes];
    for (int k = 0; k < sim::collision::kQuadLanes; ++k) a[k] = &placedA[first + k], b[k] = &placedB[first + k];
    Manifold wide[sim::collision::kQuadLanes];
    sim::collision::collideQuadPairs(a, b, margin, wide, sideSlack);
    for (int k = 0; k < sim::collision::kQuadLanes; ++k) {
      const Manifold one = sim::collision::collide(*a[k], *b[k], margin, sideSlack);
      CAPTURE(first + k);
      CAPTURE(describe(one));
      CAPTURE(describe(wide[k]));
      CHECK(same(wide[k], one));
      touching += one.count > 0;
    }
  }
  return touching;
}

Posed box(double w, double h, const Vec2& x, double angle) { return {sim::core::makeBox(w, h), Pose{x, Rot::fromAngle(angle)}}; }

}  // namespace

TEST_CASE("four box pairs at once are collide()'s manifolds to the bit: random poses near contact") {
  MESSAGE("four lanes in AVX2 here: " << std::string(sim::core::avx2Available() ? "yes" : "no (one pair at a time)"));
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::pair<Posed, Posed>> pairs;
  for (int i = 0; i < 4000; ++i) {
    const double wa = 0.2 + 2.0 * u(rng), ha = 0.2 + 2.0 * u(rng), wb = 0.2 + 2.0 * u(rng), hb = 0.2 + 2.0 * u(rng);
    const double angleA = 6.3 * u(rng), angleB = 6.3 * u(rng);
    // B's center at about the distance where the two touch, give or take
    const double direction = 6.3 * u(rng), reach = 0.5 * (std::hypot(wa, ha) + std::hypot(wb, hb)) * (0.4 + 0.7 * u(rng));
    pairs.emplace_back(box(wa, ha, Vec2(u(rng), u(rng)), angleA),
                       box(wb, hb, Vec2(reach * std::cos(direction), reach * std::sin(direction)), angleB));
  }
  const int touching = compare(pairs, sim::core::settings::kContactMargin);
  MESSAGE(touching << " of " << pairs.size() << " pairs touch");
  CHECK(touching > 1000);
  CHECK(touching < 3900);
  // and with the sequential solver's side slack (which keeps the points of a few more pairs)
  CHECK(compare(pairs, sim::core::settings::kContactMargin, sim::core::settings::kClipSideSlack) >= touching);
}

TEST_CASE("four box pairs at once are collide()'s manifolds to the bit: exact ties of a pile") {
  // unit boxes stacked and side by side, exactly and a hair off, level and turned by round-off: the
  // separations tie, so the first edge and vertex must be chosen as collide() chooses them
  std::vector<std::pair<Posed, Posed>> pairs;
  for (double dx : {0.0, 0.5, 1.0, 0.25, -0.5, 1.0 + 1e-12, 1e-15})
    for (double dy : {1.0, 0.0, 0.999, 1.0 - 1e-12, 1.005, 0.5})
      for (double turn : {0.0, 1e-12, -1e-9, 3.14159265358979323846 / 2, 3.14159265358979323846, 0.3})
        pairs.emplace_back(box(1, 1, Vec2(0, 0), 0.0), box(1, 1, Vec2(dx, dy), turn));
  // corner against corner: the clipping keeps nothing, collide() finishes those lanes
  for (double gap : {0.0, 0.001, -0.001, 0.02})
    for (double turn : {3.14159265358979323846 / 4, 0.7})
      pairs.emplace_back(box(1, 1, Vec2(0, 0), 3.14159265358979323846 / 4), box(1, 1, Vec2(std::sqrt(2.0) + gap, 0), turn));
  while (pairs.size() % sim::collision::kQuadLanes) pairs.push_back(pairs.front());
  const int touching = compare(pairs, sim::core::settings::kContactMargin);
  CHECK(touching > 50);
  // (the slack keeps the points of a few more pairs, corners a hair past each other)
  CHECK(compare(pairs, sim::core::settings::kContactMargin, sim::core::settings::kClipSideSlack) >= touching);
}

// libFuzzer target: the pair collision functions on random convex polygons (and circles) in random
// poses. Each must return without a crash or a sanitizer report, and the verdicts must be
// symmetric: the separating-axis separation is the same both ways, and when A overlaps B, B
// overlaps A at the same depth (within the reference edge's hysteresis). Two quadrilaterals are
// also collided four pairs at once (quad_pairs.h), which must give collide()'s manifolds to the bit.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "sim/collision/collide.h"
#include "sim/collision/quad_pairs.h"
#include "sim/core/settings.h"

namespace {

using sim::core::Vec2;

// reads doubles from the input, each mapped into [-range, range] (0 once the input is used up)
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  double next(double range) {
    uint32_t raw = 0;
    for (int k = 0; k < 4; ++k) raw = raw << 8 | (at_ < size_ ? data_[at_++] : 0);
    return range * (2.0 * raw / 4294967295.0 - 1.0);
  }
  int small(int most) { return at_ < size_ ? data_[at_++] % (most + 1) : 0; }

 private:
  const uint8_t* data_;
  size_t size_, at_ = 0;
};

// a circle, or a convex polygon of 3 to 10 vertices on an ellipse at sorted angles; false when
// the vertices make no valid polygon (makePolygon refuses it)
bool shape(Bytes& in, sim::core::Shape& out) {
  const int n = in.small(10);
  if (n < 3) {
    out = sim::core::makeCircle(0.01 + std::abs(in.next(5.0)));
    return true;
  }
  const double rx = 0.01 + std::abs(in.next(5.0)), ry = 0.01 + std::abs(in.next(5.0));
  std::vector<double> angles;
  for (int k = 0; k < n; ++k) angles.push_back(in.next(M_PI));
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2> v;
  for (double a : angles) v.emplace_back(rx * std::cos(a), ry * std::sin(a));
  try {
    out = sim::core::makePolygon(v);
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

sim::core::Pose pose(Bytes& in) {
  sim::core::Pose p;
  p.x = Vec2(in.next(10.0), in.next(10.0));
  p.q = sim::core::Rot::fromAngle(in.next(M_PI));
  return p;
}

// every field the same to the bit (a sign of zero too)
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(const sim::collision::Manifold& a, const sim::collision::Manifold& b) {
  bool ok = same(a.normal.x(), b.normal.x()) && same(a.normal.y(), b.normal.y()) && a.count == b.count &&
            same(a.separation, b.separation) && a.sat.valid == b.sat.valid && same(a.sat.separation, b.sat.separation) &&
            a.sat.referenceOnA == b.sat.referenceOnA && a.sat.referenceEdge == b.sat.referenceEdge &&
            a.sat.incidentVertex == b.sat.incidentVertex;
  for (int k = 0; k < 2; ++k)
    ok = ok && same(a.points[k].point.x(), b.points[k].point.x()) && same(a.points[k].point.y(), b.points[k].point.y()) &&
         same(a.points[k].separation, b.points[k].separation) && a.points[k].id == b.points[k].id;
  return ok;
}

// two quadrilaterals both ways, four lanes at once, against collide() one pair at a time
void checkQuads(const sim::core::Shape& a, const sim::core::Pose& pa, const sim::core::Shape& b, const sim::core::Pose& pb,
                double margin) {
  sim::collision::PlacedShape A, B;
  sim::collision::place(a, pa, A);
  sim::collision::place(b, pb, B);
  if (!sim::collision::isQuadPair(A, B)) return;
  const sim::collision::PlacedShape* first[sim::collision::kQuadLanes] = {&A, &B, &A, &B};
  const sim::collision::PlacedShape* second[sim::collision::kQuadLanes] = {&B, &A, &B, &A};
  // with and without the sequential solver's side slack
  for (double slack : {0.0, sim::core::settings::kClipSideSlack}) {
    sim::collision::Manifold lanes[sim::collision::kQuadLanes];
    sim::collision::collideQuadPairs(first, second, margin, lanes, slack);
    for (int k = 0; k < sim::collision::kQuadLanes; ++k)
      if (!same(lanes[k], sim::collision::collide(*first[k], *second[k], margin, slack))) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  sim::core::Shape a, b;
  if (!shape(in, a) || !shape(in, b)) return 0;
  const sim::core::Pose pa = pose(in), pb = pose(in);
  const double margin = std::abs(in.next(0.1));
  const sim::collision::Manifold ab = sim::collision::collide(a, pa, b, pb, margin);
  const sim::collision::Manifold ba = sim::collision::collide(b, pb, a, pa, margin);
  sim::collision::bounds(a, pa);
  // the notes' separation(P, Q) is symmetric by definition: the larger of the two one-way ones
  const sim::collision::SatFeatures sab = sim::collision::sat(a, pa, b, pb), sba = sim::collision::sat(b, pb, a, pa);
  const double scale = 1.0 + pa.x.norm() + pb.x.norm();
  if (sab.valid != sba.valid || (sab.valid && std::abs(sab.separation - sba.separation) > 1e-12 * scale)) std::abort();
  // overlapping pairs: both orders find the contact, at depths that differ at most by the
  // hysteresis with which each order keeps its first shape's edge (settings.h). Pairs apart within
  // the margin are not compared: there each order's points bound the gap from its own reference
  // edge, and the two bounds may differ by more.
  const double slack = sim::core::settings::kReferenceEdgeHysteresis + 1e-9 * scale;
  if ((ab.separation < -slack && ba.count == 0) || (ba.separation < -slack && ab.count == 0)) std::abort();
  if (ab.separation < -slack && ba.separation < -slack && std::abs(ab.separation - ba.separation) > slack) std::abort();
  checkQuads(a, pa, b, pb, margin);
  return 0;
}

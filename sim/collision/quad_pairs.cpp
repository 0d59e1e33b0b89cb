#include "sim/collision/quad_pairs.h"

#include "sim/collision/quad_lanes.h"
#include "sim/core/settings.h"
#include "sim/core/simd_support.h"

namespace sim::collision {

void collideQuadPairs(const PlacedShape* const a[kQuadLanes], const PlacedShape* const b[kQuadLanes], double margin,
                      Manifold out[kQuadLanes]) {
  static_assert(kQuadLanes == quad::kLanes, "one lane a pair");
  // (without AVX2 here, one pair at a time)
  if (!sim::core::avx2Available()) {
    for (int k = 0; k < kQuadLanes; ++k) out[k] = collide(*a[k], *b[k], margin);
    return;
  }
  quad::Input in;
  // (a Vec2 is its x and y side by side, so four of them are the eight numbers the lanes read)
  for (int k = 0; k < kQuadLanes; ++k) {
    in.av[k] = a[k]->vertices.front().data(), in.an[k] = a[k]->normals.front().data();
    in.bv[k] = b[k]->vertices.front().data(), in.bn[k] = b[k]->normals.front().data();
  }
  quad::Output lanes[kQuadLanes];
  quad::collideLanes(in, margin, sim::core::settings::kReferenceEdgeHysteresis, lanes);
  for (int k = 0; k < kQuadLanes; ++k) {
    const quad::Output& o = lanes[k];
    if (o.again) {
      out[k] = collide(*a[k], *b[k], margin);
      continue;
    }
    Manifold& m = out[k];
    m = Manifold{};
    m.normal = Vec2(o.normalX, o.normalY);
    m.count = o.count;
    for (int p = 0; p < 2; ++p) m.points[p] = {Vec2(o.pointX[p], o.pointY[p]), o.pointSeparation[p], o.id[p]};
    m.sat = {true, o.satSeparation, o.satReferenceOnA, o.satReferenceEdge, o.satIncidentVertex};
    m.separation = o.separation;
  }
}

}  // namespace sim::collision

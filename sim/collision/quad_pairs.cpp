#include "sim/collision/quad_pairs.h"

#include "sim/collision/quad_lanes.h"
#include "sim/core/settings.h"
#include "sim/core/simd_support.h"

namespace sim::collision {

using sim::core::Vec2;
void collideQuadPairs(const PlacedShape* const a[kQuadLanes], const PlacedShape* const b[kQuadLanes], double margin,
                      Manifold out[kQuadLanes], double sideSlack) {
  static_assert(kQuadLanes == quad::kLanes, "one lane a pair");
  // (without AVX2 here, one pair at a time)
  if (!sim::core::avx2Available()) {
    for (int k = 0; k < kQuadLanes; ++k) out[k] = collide(*a[k], *b[k], margin, sideSlack);
    return;
  }
  quad::Input in;
  // (a Vec2 is its x and y side by side, so four of them are the eight numbers the lanes read)
  for (int k = 0; k < kQuadLanes; ++k) {
    in.av[k] = a[k]->vertices.front().data(), in.an[k] = a[k]->normals.front().data();
    in.bv[k] = b[k]->vertices.front().data(), in.bn[k] = b[k]->normals.front().data();
  }
  quad::Output lanes;
  quad::collideLanes(in, margin, sim::core::settings::kReferenceEdgeHysteresis, sideSlack, lanes);
  for (int k = 0; k < kQuadLanes; ++k) {
    if (lanes.again[k]) {
      out[k] = collide(*a[k], *b[k], margin, sideSlack);
      continue;
    }
    Manifold& m = out[k];
    m.normal = Vec2(lanes.normalX[k], lanes.normalY[k]);
    m.count = static_cast<int>(lanes.count[k]);
    for (int p = 0; p < 2; ++p)
      m.points[p] = {Vec2(lanes.pointX[p][k], lanes.pointY[p][k]), lanes.pointSeparation[p][k],
                     static_cast<FeatureId>(lanes.id[p][k])};
    m.sat = {true, lanes.satSeparation[k], lanes.satReferenceOnA[k] != 0, static_cast<int>(lanes.satReferenceEdge[k]),
             static_cast<int>(lanes.satIncidentVertex[k])};
    m.separation = lanes.separation[k];
  }
}

}  // namespace sim::collision

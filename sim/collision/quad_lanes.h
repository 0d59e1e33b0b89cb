// What the AVX2 unit of the quad pairs (quad_lanes_wide.cpp) reads and writes: plain numbers, no
// Eigen and no standard library templates, since that unit is compiled with -mavx2 and must share
// no inline function with the rest of the program (quad_pairs.cpp converts to and from Manifold).
#pragma once

#include <cstdint>

namespace sim::collision::quad {

constexpr int kLanes = 4;

// each lane's two polygons: four vertices and four outward edge normals, as x, y pairs in order
struct Input {
  const double* av[kLanes];
  const double* an[kLanes];
  const double* bv[kLanes];
  const double* bn[kLanes];
};

// one lane's manifold, field for field collide()'s Manifold
struct Output {
  double normalX, normalY;
  int count;
  double pointX[2], pointY[2], pointSeparation[2];
  std::uint64_t id[2];
  double satSeparation;
  bool satReferenceOnA;
  int satReferenceEdge, satIncidentVertex;
  double separation;
  // the lane's clipping kept no point within the margin of a touching pair: collide() finishes it
  // (the best edge's clipping, or a corner against a corner)
  bool again;
};

// the four lanes; `hysteresis` is settings::kReferenceEdgeHysteresis
void collideLanes(const Input& in, double margin, double hysteresis, Output out[kLanes]);

}  // namespace sim::collision::quad

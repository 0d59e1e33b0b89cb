// What the AVX2 unit of the quad pairs (quad_lanes_wide.cpp) reads and writes: plain numbers, no
// Eigen and no standard library templates, since that unit is compiled with -mavx2 and must share
// no inline function with the rest of the program (quad_pairs.cpp converts to and from Manifold).
#pragma once

namespace sim::collision::quad {

constexpr int kLanes = 4;

// each lane's two polygons: four vertices and four outward edge normals, as x, y pairs in order
struct Input {
  const double* av[kLanes];
  const double* an[kLanes];
  const double* bv[kLanes];
  const double* bn[kLanes];
};

// the four lanes' manifolds, field for field collide()'s Manifold, each field for the four lanes
// side by side (stored a register at a time); flags are 0 or all ones
struct Output {
  alignas(32) double normalX[kLanes];
  alignas(32) double normalY[kLanes];
  alignas(32) long long count[kLanes];
  alignas(32) double pointX[2][kLanes];
  alignas(32) double pointY[2][kLanes];
  alignas(32) double pointSeparation[2][kLanes];
  alignas(32) long long id[2][kLanes];  // FeatureId's bits, as the lanes hold them
  alignas(32) double satSeparation[kLanes];
  alignas(32) long long satReferenceOnA[kLanes];
  alignas(32) long long satReferenceEdge[kLanes];
  alignas(32) long long satIncidentVertex[kLanes];
  alignas(32) double separation[kLanes];
  // the lane's clipping kept no point within the margin of a touching pair, or found no edge:
  // collide() finishes it (the best edge's clipping, or a corner against a corner)
  alignas(32) long long again[kLanes];
};

// the four lanes; `hysteresis` is settings::kReferenceEdgeHysteresis
void collideLanes(const Input& in, double margin, double hysteresis, double sideSlack, Output& out);

}  // namespace sim::collision::quad

// The solids of 3D frames as triangle meshes in body coordinates: a box's six faces (flat, its
// twelve edges outlined), an ellipsoid's latitude-longitude grid (smooth, its silhouette and its
// three principal ellipses outlined, so that a turning sphere is seen to turn).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "render/draw3d/camera3d.h"
#include "sim/world3d/shape.h"

namespace render::draw3d {

struct Mesh {
  std::string name;                                     // e.g. "box 0.1 0.4 0.8", for draw lists
  std::vector<sim::world3d::Vec3> positions;            // body coordinates
  std::vector<sim::world3d::Vec3> normals;              // per position, outward, unit
  std::vector<std::array<int, 3>> triangles;            // counter-clockwise seen from outside
  std::vector<std::array<int, 2>> creases;              // edges always outlined (a box's)
  std::vector<std::vector<sim::world3d::Vec3>> curves;  // closed lines on the surface always drawn, body coordinates
  // a smooth mesh's interior edges (a, b) with the two triangles that share them: an edge is on the
  // silhouette when one of them faces the eye and the other does not
  std::vector<std::array<int, 4>> edges;
};

Mesh boxMesh(const sim::world3d::Vec3& sides);
// a square of `side` in the body's xy plane, facing +z (a plane obstacle's visible patch), ruled
// into `cells` × `cells` squares whose lines are its creases, so that its tilt and depth show
Mesh planeMesh(double side, int cells);
// `rings` latitudes from pole to pole, `segments` longitudes: at 24 × 48 the silhouette's facets
// are under a pixel for an ellipsoid 300 px across
Mesh ellipsoidMesh(const sim::world3d::Vec3& semiAxes, int rings = 24, int segments = 48);
Mesh meshOf(const sim::world3d::Shape& shape);
// the same with `segments` longitudes for an ellipsoid (latitudes half as many), a level of detail
// for its size on screen: below kOutlinedSegments its surface curves are left out, and at
// kLeastSegments its silhouette too (a body a pixel or two across shows as its shaded fill)
inline constexpr int kLeastSegments = 6, kOutlinedSegments = 12;
Mesh meshOf(const sim::world3d::Shape& shape, int segments);
// the longitudes an ellipsoid `radiusPx` pixels across the frame needs: its facets within 0.05 px
// of the surface (n = π / acos(1 − 0.05 / r), as 2D discs), from kLeastSegments to 48 in a few
// levels, so that bodies of about one size share one mesh
int segmentsFor(double radiusPx);

// whether triangle t of the mesh faces a point (body coordinates)
bool facing(const Mesh& mesh, int triangle, const sim::world3d::Vec3& point);
// the silhouette seen from `eye` (body coordinates): the smooth mesh's edges between a triangle
// facing it and one facing away
std::vector<std::array<int, 2>> silhouette(const Mesh& mesh, const sim::world3d::Vec3& eye);

}  // namespace render::draw3d

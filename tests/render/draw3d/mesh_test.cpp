// The meshes of the 3D shapes: closed, wound outward (the volume by the divergence theorem is the
// shape's), a box's twelve creases its edges, an ellipsoid's silhouette a loop around it.
#include "render/draw3d/mesh.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace render::draw3d;
using sim::world3d::Vec3;

namespace {

// the enclosed volume, Σ a·(b × c)/6 over the triangles: positive only when they face outward
double volume(const Mesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
  return v;
}

}  // namespace

TEST_CASE("a box: six faces wound outward, twelve creases as long as its sides") {
  const Mesh m = boxMesh(Vec3(0.2, 0.4, 0.8));
  CHECK(m.name == "box 0.2 0.4 0.8");
  CHECK(m.triangles.size() == 12);
  CHECK(volume(m) == doctest::Approx(0.2 * 0.4 * 0.8));
  REQUIRE(m.creases.size() == 12);
  int counts[3] = {0, 0, 0};
  for (const auto& e : m.creases) {
    REQUIRE(e[0] >= 0);
    REQUIRE(e[1] >= 0);
    const double length = (m.positions[e[0]] - m.positions[e[1]]).norm();
    for (int k = 0; k < 3; ++k) counts[k] += std::abs(length - Vec3(0.2, 0.4, 0.8)[k]) < 1e-12;
  }
  CHECK(counts[0] == 4);
  CHECK(counts[1] == 4);
  CHECK(counts[2] == 4);
  // flat faces: a face's normal at each of its corners
  for (size_t i = 0; i < m.positions.size(); ++i) CHECK(m.normals[i].dot(m.positions[i]) > 0.0);
}

TEST_CASE("an ellipsoid: closed and wound outward, its volume 4/3 π a b c to the tessellation") {
  const Vec3 axes(0.3, 0.2, 0.1);
  const Mesh m = ellipsoidMesh(axes);
  const double exact = 4.0 / 3.0 * std::numbers::pi * axes.prod();
  CHECK(volume(m) == doctest::Approx(exact).epsilon(0.01));
  CHECK(volume(m) < exact);  // inscribed
  // every edge between two triangles: a closed surface
  CHECK(m.edges.size() * 2 == m.triangles.size() * 3);
  CHECK(m.curves.size() == 3);
  // seen from far along z: the silhouette is the equator's ring, one edge per longitude
  const auto outline = silhouette(m, Vec3(0, 0, 100));
  CHECK(outline.size() == 48);
  for (const auto& e : outline) CHECK(std::abs(m.positions[e[0]].z()) < 0.1 * axes.z());
}

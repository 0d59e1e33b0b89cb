#include "render/draw3d/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

namespace render::draw3d {

using sim::world3d::Vec3;
namespace {

std::string named(const char* kind, const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s %g %g %g", kind, v.x(), v.y(), v.z());
  return buf;
}

// the ellipse of the shape in the plane normal to axis k, `points` points
std::vector<Vec3> principalEllipse(const Vec3& semiAxes, int k, int points) {
  std::vector<Vec3> curve;
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  for (int i = 0; i < points; ++i) {
    const double a = 2.0 * std::numbers::pi * i / points;
    Vec3 p = Vec3::Zero();
    p[u] = semiAxes[u] * std::cos(a);
    p[v] = semiAxes[v] * std::sin(a);
    curve.push_back(p);
  }
  return curve;
}

}  // namespace

Mesh boxMesh(const Vec3& sides) {
  Mesh m;
  m.name = named("box", sides);
  const Vec3 h = 0.5 * sides;
  // each face: its outward axis, and its four corners counter-clockwise seen from outside
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 n = Vec3::Zero();
      n[axis] = sign;
      const int first = static_cast<int>(m.positions.size());
      // (u, v) around the face; reversed on the negative side so that the winding faces out
      const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int c = 0; c < 4; ++c) {
        Vec3 p;
        p[axis] = sign * h[axis];
        p[u] = corners[c][0] * h[u];
        p[v] = sign * corners[c][1] * h[v];
        m.positions.push_back(p);
        m.normals.push_back(n);
      }
      m.triangles.push_back({first, first + 1, first + 2});
      m.triangles.push_back({first, first + 2, first + 3});
    }
  // the twelve edges, once each: from the faces of positive sign and the four sides around each
  // axis, as pairs of corner positions looked up among the faces' vertices
  auto index = [&](const Vec3& p) {
    for (size_t i = 0; i < m.positions.size(); ++i)
      if ((m.positions[i] - p).norm() < 1e-12 * (1.0 + h.norm())) return static_cast<int>(i);
    return -1;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double su : {-1.0, 1.0})
      for (double sv : {-1.0, 1.0}) {
        Vec3 a, b;
        a[axis] = -h[axis], b[axis] = h[axis];
        a[u] = b[u] = su * h[u];
        a[v] = b[v] = sv * h[v];
        m.creases.push_back({index(a), index(b)});
      }
  }
  return m;
}

Mesh ellipsoidMesh(const Vec3& semiAxes, int rings, int segments) {
  Mesh m;
  m.name = named("ellipsoid", semiAxes);
  // the unit sphere's point u, stretched: p = A u, its normal ∝ A⁻¹ u
  auto add = [&](const Vec3& u) {
    m.positions.push_back(semiAxes.cwiseProduct(u));
    m.normals.push_back(u.cwiseQuotient(semiAxes).normalized());
  };
  add(Vec3(0, 0, -1));
  for (int r = 1; r < rings; ++r) {
    const double lat = std::numbers::pi * (static_cast<double>(r) / rings - 0.5);
    for (int s = 0; s < segments; ++s) {
      const double lon = 2.0 * std::numbers::pi * s / segments;
      add(Vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)));
    }
  }
  add(Vec3(0, 0, 1));
  const int top = static_cast<int>(m.positions.size()) - 1;
  auto at = [&](int ring, int s) { return 1 + (ring - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({0, at(1, s + 1), at(1, s)});
    for (int r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
    m.triangles.push_back({top, at(rings - 1, s), at(rings - 1, s + 1)});
  }
  // every edge with the two triangles on either side of it
  std::map<std::pair<int, int>, std::vector<int>> sides;
  for (size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      sides[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
    }
  for (const auto& [edge, triangles] : sides)
    if (triangles.size() == 2) m.edges.push_back({edge.first, edge.second, triangles[0], triangles[1]});
  for (int k = 0; k < 3; ++k) m.curves.push_back(principalEllipse(semiAxes, k, 2 * segments));
  return m;
}

Mesh planeMesh(double side, int cells) {
  Mesh m;
  m.name = "plane " + std::to_string(side) + " " + std::to_string(cells);
  const int n = cells + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.positions.push_back(
          Vec3(side * (static_cast<double>(i) / cells - 0.5), side * (static_cast<double>(j) / cells - 0.5), 0.0));
      m.normals.push_back(Vec3::UnitZ());
    }
  const auto at = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      // counter-clockwise seen from +z
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < cells; ++l) {
      m.creases.push_back({at(l, k), at(l + 1, k)});
      m.creases.push_back({at(k, l), at(k, l + 1)});
    }
  return m;
}

Mesh meshOf(const sim::world3d::Shape& shape) {
  switch (shape.kind) {
    case sim::world3d::ShapeKind::Box: return boxMesh(shape.sides);
    case sim::world3d::ShapeKind::Sphere: return ellipsoidMesh(Vec3::Constant(shape.radius));
    case sim::world3d::ShapeKind::Ellipsoid: return ellipsoidMesh(shape.semiAxes);
  }
  return {};
}

Mesh meshOf(const sim::world3d::Shape& shape, int segments) {
  if (shape.kind == sim::world3d::ShapeKind::Box) return boxMesh(shape.sides);
  const Vec3 semiAxes = shape.kind == sim::world3d::ShapeKind::Sphere ? Vec3::Constant(shape.radius) : shape.semiAxes;
  Mesh m = ellipsoidMesh(semiAxes, std::max(2, segments / 2), segments);
  if (segments < kOutlinedSegments) m.curves.clear();
  if (segments <= kLeastSegments) m.edges.clear();
  return m;
}

int segmentsFor(double radiusPx) {
  constexpr int kLevels[] = {kLeastSegments, 8, 12, 16, 24, 32, 48};
  const double r = radiusPx;
  if (!(r > 0.05)) return kLeastSegments;
  const double n = std::numbers::pi / std::acos(1.0 - 0.05 / r);
  for (int level : kLevels)
    if (n <= level) return level;
  return 48;
}

bool facing(const Mesh& m, int t, const Vec3& point) {
  const std::array<int, 3>& tri = m.triangles[t];
  const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]], &c = m.positions[tri[2]];
  return (b - a).cross(c - a).dot(point - a) > 0.0;
}

std::vector<std::array<int, 2>> silhouette(const Mesh& m, const Vec3& eye) {
  std::vector<bool> front(m.triangles.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) front[t] = facing(m, static_cast<int>(t), eye);
  std::vector<std::array<int, 2>> out;
  for (const std::array<int, 4>& e : m.edges)
    if (front[e[2]] != front[e[3]]) out.push_back({e[0], e[1]});
  return out;
}

}  // namespace render::draw3d

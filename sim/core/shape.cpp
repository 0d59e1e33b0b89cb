#include "sim/core/shape.h"

#include <algorithm>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/core/settings.h"

namespace sim::core {

Shape makeCircle(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("circle radius must be a positive finite number");
  Shape s;
  s.kind = ShapeKind::Circle;
  s.radius = radius;
  return s;
}

Shape makeBox(double width, double height) {
  if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height))
    throw std::invalid_argument("box width and height must be positive finite numbers");
  const double w = 0.5 * width, h = 0.5 * height;
  return makePolygon({{-w, -h}, {w, -h}, {w, h}, {-w, h}});
}

Shape makePlane(const Vec2& normal) {
  if (!isFinite(normal) || normal.norm() == 0.0)
    throw std::invalid_argument("a plane's normal must be a non-zero vector, e.g. [0, 1] for a floor");
  Shape s;
  s.kind = ShapeKind::Plane;
  s.planeNormal = normal.normalized();
  return s;
}

namespace {

double signedArea(const std::vector<Vec2>& v) {
  double twice = 0.0;
  for (size_t i = 0; i < v.size(); ++i) twice += cross(v[i], v[(i + 1) % v.size()]);
  return 0.5 * twice;
}

}  // namespace

Shape makePolygon(std::vector<Vec2> v) {
  const size_t n = v.size();
  if (n < 3) throw std::invalid_argument("a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (const Vec2& p : v)
    if (!isFinite(p)) throw std::invalid_argument("polygon vertices must be finite numbers");

  // accept either winding; store counter-clockwise
  if (signedArea(v) < 0.0) std::reverse(v.begin(), v.end());

  double size2 = 0.0;
  for (const Vec2& p : v) size2 = std::max(size2, (p - v[0]).squaredNorm());
  if (size2 == 0.0) throw std::invalid_argument("degenerate polygon: all vertices coincide");

  // convex and simple: every turn is strictly left and the turns add up to one full turn
  // (a star polygon also turns left everywhere, but winds twice)
  for (size_t i = 0; i < n; ++i)
    if ((v[(i + 1) % n] - v[i]).squaredNorm() <= settings::kPolygonTurnTolerance * size2)
      throw std::invalid_argument("degenerate polygon: two consecutive vertices coincide; remove one");
  double turning = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e0 = v[(i + 1) % n] - v[i];
    const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
    const double turn = cross(e0, e1);
    if (turn <= settings::kPolygonTurnTolerance * size2) {
      // name the vertex by its coordinates: indices change when the winding is reversed
      const Vec2& p = v[(i + 1) % n];
      std::ostringstream where;
      where << '(' << p.x() << ", " << p.y() << ')';
      const std::string at = where.str();
      if (std::abs(turn) <= settings::kPolygonTurnTolerance * size2)
        throw std::invalid_argument("degenerate polygon: vertex " + at + " lies on the line through its neighbours; remove it");
      throw std::invalid_argument("non-convex polygon: the boundary turns the wrong way at vertex " + at +
                                  "; give a convex polygon");
    }
    turning += std::atan2(turn, e0.dot(e1));
  }
  if (std::abs(turning - 2.0 * std::numbers::pi) > settings::kPolygonWindingTolerance)
    throw std::invalid_argument(
        "self-intersecting polygon: its boundary winds more than once; give the vertices of a convex polygon in order");

  Shape s;
  s.kind = ShapeKind::Polygon;
  s.vertices = std::move(v);
  s.normals.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e = s.vertices[(i + 1) % n] - s.vertices[i];
    s.normals[i] = Vec2(e.y(), -e.x()).normalized();
  }
  return s;
}

namespace {

// a part centred on its own centroid, its pose moved so that it stays where it was
ShapePart centred(ShapePart part) {
  if (part.shape.kind != ShapeKind::Polygon) return part;
  const Vec2 c = areaProperties(part.shape).centroid;
  for (Vec2& v : part.shape.vertices) v -= c;
  part.pose.x = part.pose.toWorld(c);
  return part;
}

}  // namespace

Shape makeCompound(std::vector<ShapePart> parts) {
  if (parts.size() < 2)
    throw std::invalid_argument("a body of parts needs at least two; give one shape as the body's 'shape' itself");
  for (ShapePart& part : parts) {
    if (part.shape.kind != ShapeKind::Circle && part.shape.kind != ShapeKind::Polygon)
      throw std::invalid_argument("each part is a box, polygon or circle");
    part = centred(std::move(part));
  }
  Shape s;
  s.kind = ShapeKind::Compound;
  s.parts = std::move(parts);
  return s;
}

Shape makePlaced(Shape shape, const Pose& pose) {
  Shape s;
  s.kind = ShapeKind::Compound;
  s.parts.push_back(centred({std::move(shape), pose}));
  return s;
}

AreaProperties areaProperties(const Shape& shape) {
  AreaProperties p;
  if (shape.kind == ShapeKind::Compound) {
    // the parts' areas summed, their centroids averaged by area, their moments moved to the
    // common centroid (parallel-axis theorem)
    for (const ShapePart& part : shape.parts) {
      const AreaProperties a = areaProperties(part.shape);
      p.area += a.area;
      p.centroid += a.area * part.pose.toWorld(a.centroid);
    }
    p.centroid /= p.area;
    for (const ShapePart& part : shape.parts) {
      const AreaProperties a = areaProperties(part.shape);
      p.secondMoment += a.secondMoment + a.area * (part.pose.toWorld(a.centroid) - p.centroid).squaredNorm();
    }
    return p;
  }
  if (shape.kind == ShapeKind::Circle) {
    const double r2 = shape.radius * shape.radius;
    p.area = std::numbers::pi * r2;
    p.secondMoment = 0.5 * p.area * r2;
    return p;
  }
  // a half-plane has no finite area: it can only be static
  if (shape.kind == ShapeKind::Plane) {
    p.area = p.secondMoment = std::numeric_limits<double>::infinity();
    return p;
  }
  // triangle fan from the first vertex, which keeps round-off small far from the origin
  // (the polygon formulas as in Box2D's b2ComputePolygonMass)
  const auto& v = shape.vertices;
  const Vec2 o = v[0];
  double area = 0.0, moment = 0.0;
  Vec2 weighted = Vec2::Zero();
  for (size_t i = 1; i + 1 < v.size(); ++i) {
    const Vec2 e1 = v[i] - o, e2 = v[i + 1] - o;
    const double twiceArea = cross(e1, e2);
    area += 0.5 * twiceArea;
    weighted += (0.5 * twiceArea / 3.0) * (e1 + e2);
    // ∫ |r|² dA over the triangle (o, e1, e2) about o
    moment += twiceArea / 12.0 * (e1.squaredNorm() + e1.dot(e2) + e2.squaredNorm());
  }
  const Vec2 c = weighted / area;
  p.area = area;
  p.centroid = o + c;
  // parallel axis theorem: move the moment from o to the centroid
  p.secondMoment = moment - area * c.squaredNorm();
  return p;
}

Shape shifted(const Shape& shape, const Vec2& origin) {
  Shape s = shape;
  for (Vec2& p : s.vertices) p -= origin;
  for (ShapePart& part : s.parts) part.pose.x -= origin;
  return s;
}

double boundingRadius(const Shape& shape) {
  if (shape.kind == ShapeKind::Circle) return shape.radius;
  if (shape.kind == ShapeKind::Plane) return std::numeric_limits<double>::infinity();
  if (shape.kind == ShapeKind::Compound) {
    double r = 0.0;
    for (const ShapePart& part : shape.parts) r = std::max(r, part.pose.x.norm() + boundingRadius(part.shape));
    return r;
  }
  double r2 = 0.0;
  for (const Vec2& p : shape.vertices) r2 = std::max(r2, p.squaredNorm());
  return std::sqrt(r2);
}

}  // namespace sim::core

// Shapes in body coordinates and the mass properties they give (notes: "Rigid body kinetic energy").
#pragma once

#include <vector>

#include "sim/core/math.h"

namespace sim::core {

enum class ShapeKind { Circle, Polygon, Plane, Compound };

struct ShapePart;

// a convex shape in body coordinates; polygons are counter-clockwise with outward edge normals
struct Shape {
  ShapeKind kind = ShapeKind::Circle;
  double radius = 0.0;               // circle
  std::vector<Vec2> vertices;        // polygon, counter-clockwise
  std::vector<Vec2> normals;         // polygon: outward unit normal of edge i, from vertex i to i + 1
  Vec2 planeNormal = Vec2::UnitY();  // plane: the solid is {r : n·r ≤ 0} in body coordinates
  std::vector<ShapePart> parts;      // compound: convex parts (circles and polygons) of one body
};

// a convex part of a compound shape: a circle or polygon centred on its own centroid, placed by
// `pose` in the body's coordinates
struct ShapePart {
  Shape shape;
  Pose pose;
};

// area, centroid and the second moment of area about the centroid (per unit density)
struct AreaProperties {
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  double secondMoment = 0.0;  // ∫ |r - c|² dA
};

Shape makeCircle(double radius);
Shape makeBox(double width, double height);
// any winding; throws std::invalid_argument naming the fault for non-convex, degenerate or
// self-intersecting input
Shape makePolygon(std::vector<Vec2> vertices);
// a half-plane through the body origin whose solid side is behind `normal` (static bodies only);
// throws std::invalid_argument for a zero or non-finite normal
Shape makePlane(const Vec2& normal);

// a body of several convex parts, each placed in the body's coordinates (polygons re-centred on
// their centroids, the pose moved to match); throws std::invalid_argument for fewer than two parts
// or a part that is not a circle or polygon (whether parts overlap is the collision layer's
// question: sim/collision/compound.h)
Shape makeCompound(std::vector<ShapePart> parts);
// one shape placed at `pose` in its body's coordinates (a circle whose center of mass is elsewhere):
// a compound of that one part
Shape makePlaced(Shape shape, const Pose& pose);

// (a compound's: of its parts at unit density, the centroid and moment of the union)
AreaProperties areaProperties(const Shape& shape);

// the same shape with its body origin moved to `origin` (vertices, or a compound's parts, shifted
// by -origin)
Shape shifted(const Shape& shape, const Vec2& origin);

// the largest distance of a shape point from the body origin (infinite for a plane)
double boundingRadius(const Shape& shape);

}  // namespace sim::core

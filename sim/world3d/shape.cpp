#include "sim/world3d/shape.h"

#include <numbers>
#include <stdexcept>
#include <string>

namespace sim::world3d {

namespace {

void requirePositive(const Vec3& lengths, const char* what) {
  if (!isFinite(lengths) || !(lengths.minCoeff() > 0.0))
    throw std::invalid_argument(std::string(what) + " must be three positive finite numbers");
}

// the inertia of a solid whose second moments ∫ x² dm, ∫ y² dm, ∫ z² dm are s, about its
// symmetry planes: I_xx = s_y + s_z and so on, no products of inertia
Mat3 fromSecondMoments(const Vec3& s) { return Vec3(s.y() + s.z(), s.x() + s.z(), s.x() + s.y()).asDiagonal(); }

}  // namespace

Shape makeBox(const Vec3& sides) {
  requirePositive(sides, "a box's sides [a, b, c]");
  return {.kind = ShapeKind::Box, .sides = sides};
}

Shape makeSphere(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("a sphere's radius must be a positive finite number");
  return {.kind = ShapeKind::Sphere, .radius = radius};
}

Shape makeEllipsoid(const Vec3& semiAxes) {
  requirePositive(semiAxes, "an ellipsoid's semi-axes [a, b, c]");
  return {.kind = ShapeKind::Ellipsoid, .semiAxes = semiAxes};
}

double volume(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Box: return shape.sides.prod();
    case ShapeKind::Sphere: return 4.0 / 3.0 * std::numbers::pi * std::pow(shape.radius, 3);
    case ShapeKind::Ellipsoid: return 4.0 / 3.0 * std::numbers::pi * shape.semiAxes.prod();
  }
  return 0.0;
}

// the closed forms of Landau & Lifshitz, Mechanics, §32, problem 2, through the second moments
// along each axis:
//   box of sides a:        ∫ x² dm = m a²/12
//   ellipsoid of semi-axes a: ∫ x² dm = m a²/5 (the unit ball's ∫ x² dV is 4π/15, its volume 4π/3)
//   sphere: the ellipsoid with a = b = c = r, so I = ⅖ m r² about every axis
MassProperties massProperties(const Shape& shape, double density) {
  if (!(density > 0.0) || !std::isfinite(density)) throw std::invalid_argument("density must be a positive finite number, kg/m³");
  MassProperties p;
  p.mass = density * volume(shape);
  switch (shape.kind) {
    case ShapeKind::Box: p.inertia = fromSecondMoments(p.mass / 12.0 * shape.sides.cwiseAbs2()); break;
    case ShapeKind::Sphere: p.inertia = fromSecondMoments(Vec3::Constant(p.mass / 5.0 * shape.radius * shape.radius)); break;
    case ShapeKind::Ellipsoid: p.inertia = fromSecondMoments(p.mass / 5.0 * shape.semiAxes.cwiseAbs2()); break;
  }
  return p;
}

double boundingRadius(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Box: return 0.5 * shape.sides.norm();
    case ShapeKind::Sphere: return shape.radius;
    case ShapeKind::Ellipsoid: return shape.semiAxes.maxCoeff();
  }
  return 0.0;
}

}  // namespace sim::world3d

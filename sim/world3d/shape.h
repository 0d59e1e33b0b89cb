// Shapes in body coordinates, centered on the center of mass, and the mass properties a uniform
// density gives them (notes: "Rigid body kinetic energy", what is I?, in 3D).
#pragma once

#include "sim/world3d/math.h"

namespace sim::world3d {

enum class ShapeKind { Box, Sphere, Ellipsoid };

// a solid in body coordinates; its axes are the body's x, y, z
struct Shape {
  ShapeKind kind = ShapeKind::Sphere;
  Vec3 sides = Vec3::Ones();     // box: full side lengths a, b, c
  double radius = 1.0;           // sphere
  Vec3 semiAxes = Vec3::Ones();  // ellipsoid: semi-axes a, b, c
};

// throw std::invalid_argument unless every length is positive and finite
Shape makeBox(const Vec3& sides);
Shape makeSphere(double radius);
Shape makeEllipsoid(const Vec3& semiAxes);

// mass and the inertia tensor I_b = ∫ ρ (|r|² 1 − r rᵀ) dV about the center, in body axes
struct MassProperties {
  double mass = 0.0;
  Mat3 inertia = Mat3::Zero();
};

double volume(const Shape& shape);
// the closed forms for a uniform density ρ, kg/m³
MassProperties massProperties(const Shape& shape, double density);
// the largest distance of a point of the shape from its center
double boundingRadius(const Shape& shape);

}  // namespace sim::world3d

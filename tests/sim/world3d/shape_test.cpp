#include "sim/world3d/shape.h"

#include <doctest/doctest.h>

#include <numbers>

#include "support/world3d_fixtures.h"

using fixtures3d::relativeError;
using namespace sim::world3d;

namespace {

// I_b = ∫ ρ (|r|² 1 − r rᵀ) dV by the midpoint rule on an n³ grid over the bounding box, counting
// the cells whose centers lie inside: independent of the closed forms, exact for the box up to the
// midpoint rule's known 1/n², within O(1/n) of a curved solid
MassProperties quadrature(const Shape& shape, double density, int n) {
  const Vec3 half = shape.kind == ShapeKind::Box      ? Vec3(0.5 * shape.sides)
                    : shape.kind == ShapeKind::Sphere ? Vec3::Constant(shape.radius)
                                                      : shape.semiAxes;
  const Vec3 cell = 2.0 * half / n;
  const double dm = density * cell.prod();
  MassProperties p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 r = -half + cell.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        if (shape.kind != ShapeKind::Box && r.cwiseQuotient(half).squaredNorm() > 1.0) continue;
        p.mass += dm;
        p.inertia += dm * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
      }
  return p;
}

// `bias`: the quadrature's known relative error of the second moments (zero for curved solids)
void checkAgainstQuadrature(const Shape& shape, double density, int n, double tolerance, double bias = 0.0) {
  const MassProperties exact = massProperties(shape, density), sum = quadrature(shape, density, n);
  MESSAGE("n = ", n, ": mass ", relativeError(sum.mass, exact.mass), ", moments ",
          relativeError(sum.inertia(0, 0), exact.inertia(0, 0)), ", ", relativeError(sum.inertia(1, 1), exact.inertia(1, 1)),
          ", ", relativeError(sum.inertia(2, 2), exact.inertia(2, 2)), " off");
  CHECK(relativeError(sum.mass, exact.mass) <= tolerance);
  for (int i = 0; i < 3; ++i) CHECK(relativeError(sum.inertia(i, i), (1.0 - bias) * exact.inertia(i, i)) <= tolerance);
  // principal axes along the body's: no products of inertia
  CHECK(exact.inertia.isDiagonal());
  CHECK(std::abs(sum.inertia(0, 1)) + std::abs(sum.inertia(0, 2)) + std::abs(sum.inertia(1, 2)) < 1e-9 * sum.inertia.trace());
}

}  // namespace

TEST_CASE("box [a, b, c]: m = ρabc, I = m/12 diag(b² + c², a² + c², a² + b²), against a quadrature") {
  const Shape box = makeBox(Vec3(0.2, 0.4, 0.6));
  const MassProperties p = massProperties(box, 50.0);
  CHECK(relativeError(p.mass, 50.0 * 0.048) < 1e-15);
  CHECK(relativeError(p.inertia(0, 0), p.mass / 12 * (0.16 + 0.36)) < 1e-15);
  // the midpoint rule sums ∫ x² dx over n cells to (1 − 1/n²) of it, and the mass exactly
  // (to the round-off of 216000 terms)
  checkAgainstQuadrature(box, 50.0, 60, 1e-10, 1.0 / (60 * 60));
}

TEST_CASE("ellipsoid [a, b, c]: m = 4/3 π ρ abc, I = m/5 diag(b² + c², ...), against a quadrature") {
  const Shape ellipsoid = makeEllipsoid(Vec3(0.3, 0.5, 0.9));
  const MassProperties p = massProperties(ellipsoid, 2.0);
  CHECK(relativeError(p.mass, 2.0 * 4.0 / 3.0 * std::numbers::pi * 0.135) < 1e-15);
  CHECK(relativeError(p.inertia(2, 2), p.mass / 5 * (0.09 + 0.25)) < 1e-15);
  // cells cut by the surface: 3e-4 off at n = 120
  checkAgainstQuadrature(ellipsoid, 2.0, 120, 1e-3);
}

TEST_CASE("sphere r: ⅖ m r² about every axis, the ellipsoid with equal semi-axes") {
  const MassProperties sphere = massProperties(makeSphere(0.5), 3.0);
  const MassProperties ellipsoid = massProperties(makeEllipsoid(Vec3::Constant(0.5)), 3.0);
  CHECK(relativeError(sphere.mass, ellipsoid.mass) < 1e-15);
  CHECK(sphere.inertia.isApprox(0.4 * sphere.mass * 0.25 * Mat3::Identity(), 1e-15));
  CHECK(sphere.inertia.isApprox(ellipsoid.inertia, 1e-15));
  checkAgainstQuadrature(makeSphere(0.5), 3.0, 120, 1e-3);
  // a cube of side s: m s²/6 about every axis
  CHECK(massProperties(makeBox(Vec3::Constant(2.0)), 1.0).inertia.isApprox(8.0 * 4.0 / 6.0 * Mat3::Identity(), 1e-15));
}

TEST_CASE("bad lengths and densities are refused; bounding radii") {
  CHECK_THROWS_AS(makeBox(Vec3(1, 0, 1)), std::invalid_argument);
  CHECK_THROWS_AS(makeSphere(-1), std::invalid_argument);
  CHECK_THROWS_AS(makeEllipsoid(Vec3(1, INFINITY, 1)), std::invalid_argument);
  CHECK_THROWS_AS(massProperties(makeSphere(1), 0.0), std::invalid_argument);
  CHECK(relativeError(boundingRadius(makeBox(Vec3(2, 3, 6))), 3.5) < 1e-15);
  CHECK(boundingRadius(makeEllipsoid(Vec3(0.1, 0.7, 0.2))) == 0.7);
  CHECK(relativeError(volume(makeSphere(1.0)), 4.0 / 3.0 * std::numbers::pi) < 1e-15);
}

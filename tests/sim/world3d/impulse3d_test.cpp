// The notes' impulse in 3D (impulse3d.cpp), against hand-computed values: the restitution law at the
// contact point, momentum and the angular momentum about the contact point kept in a frictionless
// impact, friction within Coulomb's cone.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/world3d/diagnostics.h"
#include "sim/world3d/impulse3d.h"

using namespace sim::world3d;

namespace {
// a 1 × 0.5 × 0.25 m box of 6 kg, spinning, falling onto a corner
Body fallingBox() {
  Body b = makeBody(makeBox(Vec3(1.0, 0.5, 0.25)), 6.0, massProperties(makeBox(Vec3(1.0, 0.5, 0.25)), 48.0).inertia);
  b.x = Vec3(0.1, -0.2, 0.7);
  b.q = axisAngle(Vec3(1, 2, 3), 0.8);
  b.v = Vec3(0.3, -0.1, -2.0);
  b.omega = Vec3(1.0, -2.0, 0.5);
  return b;
}
}  // namespace

TEST_CASE("a box striking the floor at a corner: γ by the notes' formula, v_n⁺ = −c_r v_n⁻ at the point") {
  Body box = fallingBox();
  const Vec3 r = box.toWorld(Vec3(0.5, 0.25, -0.125)), n = Vec3::UnitZ();
  const double cr = 0.6;
  // γ = −(1 + c_r) v_n⁻ / (m⁻¹ + n̂ · (I⁻¹ (r′ × n̂)) × r′), with I⁻¹ = R I_b⁻¹ Rᵀ: by hand
  const Vec3 rp = r - box.x;
  const double vn = n.dot(box.v + box.omega.cross(rp));
  REQUIRE(vn < 0.0);
  const Mat3 invI = box.rotation() * box.invInertiaBody * box.rotation().transpose();
  const double gamma = -(1.0 + cr) * vn / (1.0 / 6.0 + n.dot((invI * rp.cross(n)).cross(rp)));
  const Vec3 p0 = box.mass * box.v;
  const Vec3 l0 = box.worldInertia() * box.omega + (box.x - r).cross(p0);
  const ImpulseResult3 j = resolveImpact(box, nullptr, r, n, cr, 0.0);
  CHECK(j.gamma == doctest::Approx(gamma).epsilon(1e-14));
  CHECK(n.dot(box.pointVelocity(r)) == doctest::Approx(-cr * vn).epsilon(1e-13));
  // the impulse is along n̂ at r: momentum changes by j, and the angular momentum about r not at all
  CHECK((box.mass * box.v - p0 - gamma * n).norm() <= 1e-13);
  CHECK((box.worldInertia() * box.omega + (box.x - r).cross(box.mass * box.v) - l0).norm() <= 1e-12);
}

TEST_CASE("two spheres colliding off center with spin: the two-body impulse, momentum and angular momentum kept") {
  Body a = makeBody(makeSphere(0.5), 2.0), b = makeBody(makeSphere(0.3), 5.0);
  a.x = Vec3(0, 0, 0), a.v = Vec3(1, 0.2, 0), a.omega = Vec3(0, 3, 1);
  b.x = Vec3(0.7, 0.3, 0.2), b.v = Vec3(-0.5, 0, 0.1), b.omega = Vec3(2, 0, 0);
  // the normal from B to A, the point on the line of centers
  const Vec3 n = (a.x - b.x).normalized(), r = b.x + 0.3 * n;
  const double vn = n.dot(relativeVelocity(a, &b, r));
  REQUIRE(vn < 0.0);
  const Vec3 p0 = a.mass * a.v + b.mass * b.v;
  const Vec3 l0 = a.worldInertia() * a.omega + a.x.cross(a.mass * a.v) + b.worldInertia() * b.omega + b.x.cross(b.mass * b.v);
  const double e0 = kineticEnergy(a).total() + kineticEnergy(b).total();
  resolveImpact(a, &b, r, n, 1.0, 0.0);
  CHECK(n.dot(relativeVelocity(a, &b, r)) == doctest::Approx(-vn).epsilon(1e-13));
  CHECK((a.mass * a.v + b.mass * b.v - p0).norm() <= 1e-13);
  CHECK(
      (a.worldInertia() * a.omega + a.x.cross(a.mass * a.v) + b.worldInertia() * b.omega + b.x.cross(b.mass * b.v) - l0).norm() <=
      1e-13);
  // elastic and frictionless: the kinetic energy kept
  CHECK(kineticEnergy(a).total() + kineticEnergy(b).total() == doctest::Approx(e0).epsilon(1e-13));
}

TEST_CASE("friction at an impact: within the cone, and sliding stopped where the cone allows") {
  // a spinning ball landing: its point of contact slides; with μ large the sliding stops
  for (const double mu : {0.05, 10.0}) {
    CAPTURE(mu);
    Body ball = makeBody(makeSphere(0.2), 1.0);
    ball.x = Vec3(0, 0, 0.2), ball.v = Vec3(1, 0, -3), ball.omega = Vec3(0, 0, 4);
    const Vec3 r(0, 0, 0), n = Vec3::UnitZ();
    const ImpulseResult3 j = resolveImpact(ball, nullptr, r, n, 0.5, mu);
    CHECK(j.tangent.norm() <= mu * j.gamma * (1.0 + 1e-15));
    CHECK(std::abs(n.dot(j.tangent)) <= 1e-15);
    const Vec3 v = ball.pointVelocity(r);
    if (mu > 1.0) CHECK((v - n.dot(v) * n).norm() <= 1e-13);
    else CHECK(j.tangent.norm() == doctest::Approx(mu * j.gamma).epsilon(1e-14));
  }
}

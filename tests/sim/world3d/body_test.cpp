#include "sim/world3d/body.h"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>

#include "support/world3d_fixtures.h"

using namespace sim::world3d;
using fixtures3d::relativeError;

namespace {

// a rigid body made of point masses at body points: L and I from the sums, independent of I_b
struct PointMasses {
  std::vector<double> m;
  std::vector<Vec3> rb;  // body coordinates, center of mass at the origin
  Mat3 inertia() const {
    Mat3 i = Mat3::Zero();
    for (size_t k = 0; k < m.size(); ++k) i += m[k] * (rb[k].squaredNorm() * Mat3::Identity() - rb[k] * rb[k].transpose());
    return i;
  }
};

PointMasses lopsidedCross() {
  // three pairs of opposite masses along skewed directions: a full tensor with products of inertia
  PointMasses p;
  const Vec3 d[] = {Vec3(1, 0.2, 0), Vec3(0, 0.7, 0.3), Vec3(0.2, -0.1, 0.4)};
  const double m[] = {1.0, 2.0, 3.0};
  for (int k = 0; k < 3; ++k) {
    p.m.insert(p.m.end(), {m[k], m[k]});
    p.rb.insert(p.rb.end(), {d[k], -d[k]});
  }
  return p;
}

}  // namespace

TEST_CASE("mass properties given outright: a full tensor, its principal moments and axes") {
  const PointMasses cross = lopsidedCross();
  const Body b = makeBody(makeSphere(1), 12.0, cross.inertia());
  const Eigen::SelfAdjointEigenSolver<Mat3> check(cross.inertia());
  CHECK(b.principalMoments.isApprox(check.eigenvalues(), 1e-14));
  for (int i = 0; i < 3; ++i) {
    const Vec3 axis = b.principalAxes.col(i);
    CHECK(std::abs(axis.norm() - 1.0) < 1e-14);
    CHECK((cross.inertia() * axis).isApprox(b.principalMoments[i] * axis, 1e-12));
  }
  CHECK((b.inertiaBody * b.invInertiaBody).isApprox(Mat3::Identity(), 1e-14));
  // a flat plate meets the triangle inequality with equality: accepted
  CHECK_NOTHROW(makeBody(makeBox(Vec3(1, 2, 1e-9)), 1.0, Vec3(1, 2, 3).asDiagonal()));
}

TEST_CASE("impossible mass properties are refused, naming the fault") {
  const Shape s = makeSphere(1);
  CHECK_THROWS_WITH_AS(makeBody(s, 0.0, Mat3::Identity()), doctest::Contains("mass"), std::invalid_argument);
  Mat3 skew = Mat3::Identity();
  skew(0, 1) = 0.1;
  CHECK_THROWS_WITH_AS(makeBody(s, 1.0, skew), doctest::Contains("symmetric"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(makeBody(s, 1.0, Vec3(1, -1, 1).asDiagonal()), doctest::Contains("positive"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(makeBody(s, 1.0, Vec3(1, 1, 3).asDiagonal()), doctest::Contains("triangle inequality"),
                       std::invalid_argument);
}

TEST_CASE("L = R I_b Rᵀ ω agrees with Σ m r′ × (ω × r′) over the body's points, at any orientation") {
  const PointMasses cross = lopsidedCross();
  Body b = makeBody(makeSphere(1), 12.0, cross.inertia());
  const Vec3 axis(0.3, -1.0, 0.5);
  b.q = axisAngle(axis, 2.2);
  b.omega = Vec3(1.5, -0.4, 2.0);
  const Mat3 r = Eigen::AngleAxisd(2.2, axis.normalized()).toRotationMatrix();  // independent R
  Vec3 l = Vec3::Zero();
  double kinetic = 0.0;
  for (size_t k = 0; k < cross.m.size(); ++k) {
    const Vec3 offset = r * cross.rb[k];
    const Vec3 u = b.omega.cross(offset);
    l += cross.m[k] * offset.cross(u);
    kinetic += 0.5 * cross.m[k] * u.squaredNorm();
  }
  CHECK(b.angularMomentum().isApprox(l, 1e-14));
  CHECK(relativeError(0.5 * b.omega.dot(b.angularMomentum()), kinetic) < 1e-14);
  CHECK((b.worldInertia() * b.worldInverseInertia()).isApprox(Mat3::Identity(), 1e-14));
}

TEST_CASE("ṙ = v + ω × r′ is the rate of a body point as the body moves") {
  Body b = makeBody(makeBox(Vec3(1, 2, 3)), 1.0);
  b.x = Vec3(1, 2, 3);
  b.q = axisAngle(Vec3(1, 0, 1), 0.5);
  b.v = Vec3(0.5, 0, -1);
  b.omega = Vec3(0.2, 3.0, -1.0);
  const Vec3 rb(0.5, -1.0, 1.5);
  auto point = [&](double t) {
    BodyState s = b.state();
    s.x += t * b.v;
    s.q = rotationQuaternion(t * b.omega) * b.q;
    return s.toWorld(rb);
  };
  const double e = 1e-6;
  CHECK(b.pointVelocity(point(0)).isApprox((point(e) - point(-e)) / (2 * e), 1e-9));
}

TEST_CASE("the notes' impulse: Δp = j, I Δω = r′ × j, and ΔKE = j · (u⁻ + u⁺)/2 at the point") {
  Body b = makeBody(makeBox(Vec3(0.2, 0.4, 4.0)), 3.0, Vec3(4.0, 4.2, 0.3).asDiagonal());
  b.q = axisAngle(Vec3(1, 1, 1), 0.9);
  b.v = Vec3(0.1, -0.2, 0.3);
  b.omega = Vec3(0.5, 0.0, -0.7);
  const Body before = b;
  const Vec3 r = b.toWorld(Vec3(0.1, 0.2, 2.0)), j(1.0, -0.5, 0.25);
  b.applyImpulse(r, j);
  CHECK((b.mass * (b.v - before.v)).isApprox(j, 1e-15));
  CHECK((b.angularMomentum() - before.angularMomentum()).isApprox((r - b.x).cross(j), 1e-14));
  // the work of an impulse is j times the mean velocity of the point it acts on
  const double kineticBefore = 0.5 * before.mass * before.v.squaredNorm() + 0.5 * before.omega.dot(before.angularMomentum());
  const double kineticAfter = 0.5 * b.mass * b.v.squaredNorm() + 0.5 * b.omega.dot(b.angularMomentum());
  CHECK(relativeError(kineticAfter - kineticBefore, j.dot(0.5 * (before.pointVelocity(r) + b.pointVelocity(r)))) < 1e-13);
}

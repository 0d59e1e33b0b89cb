#include "sim/world3d/math.h"

#include <doctest/doctest.h>

#include <numbers>

using namespace sim::world3d;

namespace {

// rotations given independently of the code under test: Eigen's angle–axis matrices
Mat3 eigenRotation(const Vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

const Vec3 kAxes[] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 2, 3), Vec3(-0.3, 0.1, 0.9)};
const double kAngles[] = {0.0, 1e-9, 0.3, -1.2, std::numbers::pi, 5.0};

}  // namespace

TEST_CASE("R(q) of the quaternion of a rotation by θ about n is that rotation") {
  for (const Vec3& n : kAxes)
    for (double angle : kAngles) {
      CAPTURE(angle);
      const Quat q = axisAngle(n, angle);
      CHECK(std::abs(q.norm() - 1.0) < 1e-15);
      CHECK((rotationMatrix(q) - eigenRotation(n, angle)).cwiseAbs().maxCoeff() < 1e-15);
      // q = [cos θ/2, n sin θ/2]
      CHECK(q.w() == doctest::Approx(std::cos(angle / 2)).epsilon(1e-15));
    }
}

TEST_CASE("R(q₁ q₂) = R(q₁) R(q₂); R(q) is orthogonal with det 1 for unit q, and stretches when |q| ≠ 1") {
  const Quat a = axisAngle(Vec3(1, 2, 3), 0.7), b = axisAngle(Vec3(-1, 0, 2), 2.1);
  CHECK((rotationMatrix(a * b) - rotationMatrix(a) * rotationMatrix(b)).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((rotationMatrix(a) * rotationMatrix(a).transpose() - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-15);
  CHECK(rotationMatrix(a).determinant() == doctest::Approx(1.0).epsilon(1e-15));
  // 1 % too long: the matrix is no rotation, lengths change by O(1 %)
  const Quat longer(1.01 * a.coeffs());
  const double stretch = (rotationMatrix(longer) * Vec3(0, 1, 0)).norm();
  CHECK(std::abs(stretch - 1.0) > 1e-3);
}

TEST_CASE("q̇ = ½ (0, ω) q is the derivative of q(t) = exp(½ t ω) q₀ and is orthogonal to q") {
  const Vec3 omega(0.4, -1.0, 2.5);
  const Quat q0 = axisAngle(Vec3(1, 1, 0), 0.8);
  const double t = 0.3, e = 1e-6;
  auto q = [&](double s) { return Quat(rotationQuaternion(s * omega) * q0); };
  // central difference, error O(e²)
  const Eigen::Vector4d numeric = (q(t + e).coeffs() - q(t - e).coeffs()) / (2 * e);
  CHECK((quaternionRate(q(t), omega).coeffs() - numeric).norm() < 1e-9);
  CHECK(std::abs(quaternionRate(q(t), omega).coeffs().dot(q(t).coeffs())) < 1e-15);
  // and R(q(t)) turns at ω: Ṙ Rᵀ = ω×
  const Mat3 rDot = (rotationMatrix(q(t + e)) - rotationMatrix(q(t - e))) / (2 * e);
  const Mat3 spin = rDot * rotationMatrix(q(t)).transpose();
  CHECK(Vec3(spin(2, 1), spin(0, 2), spin(1, 0)).isApprox(omega, 1e-9));
}

TEST_CASE("exp(½ θ) at tiny angles keeps its digits") {
  const Vec3 theta(3e-9, -1e-9, 2e-9);
  const Quat q = rotationQuaternion(theta);
  CHECK(q.vec().isApprox(0.5 * theta, 1e-15));
  CHECK(rotationQuaternion(Vec3::Zero()).isApprox(Quat::Identity()));
}

TEST_CASE("a scene's quaternion: normalized within 1e-6 of unit length, refused beyond") {
  const double h = std::sqrt(0.5);
  const Quat q = unitQuaternion(0.7071068, 0.7071068, 0, 0);  // 7 digits
  CHECK(std::abs(q.norm() - 1.0) < 1e-15);
  CHECK(q.w() == doctest::Approx(h).epsilon(1e-15));
  CHECK_THROWS_WITH_AS(unitQuaternion(1, 1, 0, 0), doctest::Contains("must have unit length"), std::invalid_argument);
  CHECK_THROWS_AS(unitQuaternion(NAN, 0, 0, 0), std::invalid_argument);
  CHECK_THROWS_AS(axisAngle(Vec3::Zero(), 1.0), std::invalid_argument);
}

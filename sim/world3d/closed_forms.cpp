#include "sim/world3d/closed_forms.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace sim::world3d {

double completeEllipticKOfComplement(double kPrime) {
  if (!(kPrime > 0.0 && kPrime <= 1.0)) {
    if (kPrime == 0.0) return std::numeric_limits<double>::infinity();
    throw std::invalid_argument("the complementary modulus of K must lie in [0, 1]");
  }
  // a and g close in quadratically on AGM(1, k′)
  double a = 1.0, g = kPrime;
  while (std::abs(a - g) > settings::kEllipticTolerance * a) {
    const double mean = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = mean;
  }
  return std::numbers::pi / (2.0 * a);
}

double completeEllipticK(double k) {
  if (!(k >= 0.0 && k <= 1.0)) throw std::invalid_argument("the modulus of K must lie in [0, 1]");
  // 1 − k² as (1 − k)(1 + k), exact in the difference
  return completeEllipticKOfComplement(std::sqrt((1.0 - k) * (1.0 + k)));
}

double bodyPrecessionRate(const SymmetricTop& top) { return top.omegaBody.z() * (top.axial - top.transverse) / top.transverse; }

namespace {
Vec3 momentumBody(const SymmetricTop& top) { return Vec3(top.transverse, top.transverse, top.axial).cwiseProduct(top.omegaBody); }
}  // namespace

double spacePrecessionRate(const SymmetricTop& top) { return momentumBody(top).norm() / top.transverse; }

double coneAngle(const SymmetricTop& top) {
  const Vec3 l = momentumBody(top);
  // atan2 of |ω × L| and ω·L keeps its digits at small angles, where acos does not
  return std::atan2(top.omegaBody.cross(l).norm(), top.omegaBody.dot(l));
}

double symmetryAxisAngle(const SymmetricTop& top) {
  const Vec3 l = momentumBody(top);
  return std::atan2(Vec3(l.x(), l.y(), 0.0).norm(), l.z());
}

namespace {

// the period from the sorted moments and d_j = M² − 2 E I_j
double periodFromDifferences(const std::array<double, 3>& i, const std::array<double, 3>& d) {
  if (!(i[0] < i[1] && i[1] < i[2]))
    throw std::invalid_argument("the flip period needs three distinct principal moments (two equal ones make a symmetric top)");
  if (d[1] == 0.0) return std::numeric_limits<double>::infinity();  // on the separatrix
  // M² > 2 E I₂: ω circles the axis of I₃; otherwise the axis of I₁ (indices 1 and 3 exchanged)
  const bool aroundLargest = d[1] > 0.0;
  const double outer = aroundLargest ? i[2] - i[1] : i[1] - i[0];  // I₃ − I₂, or I₂ − I₁
  const double dFar = aroundLargest ? d[0] : -d[2];                // M² − 2 E I₁, or 2 E I₃ − M²
  const double kPrime2 = (i[2] - i[0]) * std::abs(d[1]) / (outer * dFar);
  return 4.0 * completeEllipticKOfComplement(std::sqrt(kPrime2)) * std::sqrt(i[0] * i[1] * i[2] / (outer * dFar));
}

// the moments in ascending order, and the permutation that sorts them
std::array<int, 3> ascending(const Vec3& moments) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  return order;
}

}  // namespace

double flipPeriod(const Vec3& moments, double energy, double angularMomentum) {
  const std::array<int, 3> order = ascending(moments);
  std::array<double, 3> i{}, d{};
  for (int j = 0; j < 3; ++j) {
    i[j] = moments[order[j]];
    d[j] = angularMomentum * angularMomentum - 2.0 * energy * i[j];
  }
  return periodFromDifferences(i, d);
}

double flipPeriod(const Vec3& moments, const Vec3& omega) {
  const std::array<int, 3> order = ascending(moments);
  std::array<double, 3> i{}, d{};
  for (int j = 0; j < 3; ++j) i[j] = moments[order[j]];
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) d[j] += i[k] * std::pow(omega[order[k]], 2) * (i[k] - i[j]);
  return periodFromDifferences(i, d);
}

ImpulseOutcome afterImpulse(double mass, const Mat3& inertiaBody, const Quat& q, const Vec3& velocity,
                            const Vec3& angularVelocity, const Vec3& offset, const Vec3& impulse) {
  const Mat3 r = rotationMatrix(q.normalized());
  const Mat3 inertia = r * inertiaBody * r.transpose();
  auto kinetic = [&](const Vec3& v, const Vec3& w) { return 0.5 * mass * v.dot(v) + 0.5 * w.dot(inertia * w); };
  ImpulseOutcome out;
  out.velocity = velocity + impulse / mass;
  out.angularVelocity = angularVelocity + inertia.inverse() * offset.cross(impulse);
  out.kineticEnergyBefore = kinetic(velocity, angularVelocity);
  out.kineticEnergyAfter = kinetic(out.velocity, out.angularVelocity);
  return out;
}

}  // namespace sim::world3d

#include "sim/world3d/measures.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace sim::world3d {

TurningAngle::TurningAngle(const Vec3& axis) {
  const Vec3 u = axis.normalized();
  e1_ = u.unitOrthogonal();
  e2_ = u.cross(e1_);
}

void TurningAngle::add(const Vec3& v) {
  const double a = std::atan2(v.dot(e2_), v.dot(e1_));
  if (!started_) {
    first_ = angle_ = a, started_ = true;
    return;
  }
  angle_ += std::remainder(a - std::remainder(angle_, 2 * std::numbers::pi), 2 * std::numbers::pi);
}

void SignChanges::add(double t, double f, double slope) {
  if (started_ && f != 0.0 && (f < 0.0) != (f_ < 0.0) && f_ != 0.0) {
    // the cubic of Hermite on s ∈ [0, 1], and its root by bisection (it changes sign on the interval)
    const double h = t - t_;
    auto p = [&](double s) {
      const double s2 = s * s, s3 = s2 * s;
      return (2 * s3 - 3 * s2 + 1) * f_ + (s3 - 2 * s2 + s) * h * slope_ + (-2 * s3 + 3 * s2) * f + (s3 - s2) * h * slope;
    };
    double lo = 0.0, hi = 1.0;
    const bool rising = f_ < 0.0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      ((p(mid) < 0.0) == rising ? lo : hi) = mid;
    }
    times_.push_back(t_ + 0.5 * (lo + hi) * h);
  }
  // a sample exactly at zero is skipped: the change is found between its neighbors
  if (f != 0.0 || !started_) started_ = true, t_ = t, f_ = f, slope_ = slope;
}

double SignChanges::period() const {
  if (times_.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  return 2.0 * (times_.back() - times_.front()) / static_cast<double>(times_.size() - 1);
}

int symmetryAxisIndex(const Vec3& m) { return m[1] - m[0] < m[2] - m[1] ? 2 : 0; }

Vec3 principalAxis(const Body& body, int k) {
  Vec3 a = body.principalAxes.col(k);
  Eigen::Index largest = 0;
  a.cwiseAbs().maxCoeff(&largest);
  return a[largest] < 0.0 ? Vec3(-a) : a;
}

namespace {

// ω and its rate by Euler's equations without torque, I_b ω̇ = (I_b ω) × ω, both in body coordinates
// (a right-handed frame, which the principal axes with their signs fixed need not be)
std::pair<Vec3, Vec3> bodyOmega(const Body& b) {
  const Vec3 w = b.rotation().transpose() * b.omega;
  return {w, b.invInertiaBody * (b.inertiaBody * w).cross(w)};
}

}  // namespace

FreeBodyMeasures::FreeBodyMeasures(const Body& b, double time)
    : symmetry_(symmetryAxisIndex(b.principalMoments)),
      symmetryAxis_(principalAxis(b, symmetry_)),
      middleAxis_(principalAxis(b, 1)),
      start_(time),
      now_(time),
      body_(symmetryAxis_),
      // a body at rest has no L to turn about: any axis will do
      space_(b.angularMomentum().norm() > 0.0 ? b.angularMomentum() : Vec3(Vec3::UnitZ())) {
  add(b, time);
}

void FreeBodyMeasures::add(const Body& b, double time) {
  now_ = time;
  body_.add(b.rotation().transpose() * b.omega);
  space_.add(b.rotation() * symmetryAxis_);
  const auto [w, rate] = bodyOmega(b);
  middle_.add(time, middleAxis_.dot(w), middleAxis_.dot(rate));
}

double FreeBodyMeasures::precessionRate() const {
  return now_ > start_ ? body_.turned() / (now_ - start_) : std::numeric_limits<double>::quiet_NaN();
}

double FreeBodyMeasures::spacePrecessionRate() const {
  return now_ > start_ ? space_.turned() / (now_ - start_) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace sim::world3d

// Measures of a run that the closed forms (closed_forms.h) are compared against: how far a vector
// turns about an axis, when a sampled quantity changes sign, and, for one free body, the precession
// rates and the flip period as a run shows them (tests and a scene's `expect` take them).
#pragma once

#include <vector>

#include "sim/world3d/body.h"

namespace sim::world3d {

// how far a vector turns about `axis` (right-handed), unwrapped from sample to sample: samples must
// come closer than half a turn apart
class TurningAngle {
 public:
  TurningAngle() = default;
  explicit TurningAngle(const Vec3& axis);
  void add(const Vec3& v);
  // radians turned since the first sample
  double turned() const { return angle_ - first_; }

 private:
  Vec3 e1_ = Vec3::UnitX(), e2_ = Vec3::UnitY();  // the plane normal to the axis
  double first_ = 0.0, angle_ = 0.0;
  bool started_ = false;
};

// the times at which a sampled function f(t) changes sign, each located on the cubic of Hermite
// through the two samples around it (values and slopes), so that the time is as good as the
// samples: O(h⁴) between steps h apart, where a straight line between them would give O(h²)
class SignChanges {
 public:
  void add(double t, double f, double slope);
  const std::vector<double>& times() const { return times_; }
  // the period of a function that changes sign twice a period, from the first change to the last:
  // 2 (t_last − t_first) / (changes − 1); NaN with fewer than two changes
  double period() const;

 private:
  bool started_ = false;
  double t_ = 0.0, f_ = 0.0, slope_ = 0.0;
  std::vector<double> times_;
};

// the index (0, 1 or 2, ascending moments) of a symmetric top's symmetry axis: the moment that
// differs from the two closest to each other
int symmetryAxisIndex(const Vec3& principalMoments);
// principal axis k of a body in body coordinates, turned so that its largest component is positive
// (the eigen-solver's sign is arbitrary; a box's axis k is then the body's x, y or z itself)
Vec3 principalAxis(const Body& body, int k);

// one torque-free body followed from the first sample: ω in the body turning about the symmetry
// axis, the symmetry axis turning about L in space (L of the first sample), and the sign changes of
// ω's component along the middle principal axis, with Euler's equations for its slope
class FreeBodyMeasures {
 public:
  FreeBodyMeasures(const Body& body, double time);
  void add(const Body& body, double time);

  // rad/s since the first sample: Ω of ω about the symmetry axis seen from the body, and of the
  // symmetry axis about L in space (NaN before any time has passed)
  double precessionRate() const;
  double spacePrecessionRate() const;
  // the period of ω_b along the middle axis (SignChanges::period)
  double flipPeriod() const { return middle_.period(); }
  size_t signChanges() const { return middle_.times().size(); }

 private:
  int symmetry_;
  Vec3 symmetryAxis_, middleAxis_;  // body coordinates
  double start_, now_;
  TurningAngle body_, space_;
  SignChanges middle_;
};

}  // namespace sim::world3d

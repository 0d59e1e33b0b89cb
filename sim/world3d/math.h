// 3D vectors and unit quaternions on top of Eigen, with the notes' names: x, q = [w x y z],
// R = R(q), q̇ = ½ (0, ω) q (notes: "Representing rigid body state", the 3D half).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/world3d/settings.h"

namespace sim::world3d {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// q = [w x y z] is Quat(w, x, y, z); Eigen keeps coeffs() in the order [x y z w], so the layer
// touches coeffs() only in the helpers below, where the order does not matter
using Quat = Eigen::Quaterniond;

// R(q) by the formula for a unit quaternion, evaluated as it stands: a q that has drifted from
// unit length gives a matrix that is no rotation, and a body posed with it stretches
inline Mat3 rotationMatrix(const Quat& q) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Mat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z), 1 - 2 * (x * x + z * z),
      2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

// q̇ = ½ (0, ω) q, for ω in the world frame (a tangent four-vector, not a rotation)
inline Quat quaternionRate(const Quat& q, const Vec3& omega) {
  const Quat product = Quat(0.0, omega.x(), omega.y(), omega.z()) * q;
  return Quat(0.5 * product.coeffs());
}

// q + h q̇, as four-vectors: off unit length by O(h²) until normalized
inline Quat plus(const Quat& q, double h, const Quat& qDot) { return Quat(q.coeffs() + h * qDot.coeffs()); }

// exp(½ θ): the unit quaternion of a rotation by |θ| about θ/|θ|, so that the group update
// q ← exp(½ h ω) q is rotationQuaternion(h ω) * q; sin(s)/s by its series where s is tiny
inline Quat rotationQuaternion(const Vec3& theta) {
  const double half = 0.5 * theta.norm();
  const double sincHalf = half < 1e-4 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
  const Vec3 v = 0.5 * sincHalf * theta;
  return Quat(std::cos(half), v.x(), v.y(), v.z());
}

// a rotation by `angle` (radians, right-handed) about `axis` (any length but zero)
inline Quat axisAngle(const Vec3& axis, double angle) {
  if (!(axis.norm() > 0.0) || !axis.allFinite())
    throw std::invalid_argument("a rotation axis must be a non-zero finite vector, e.g. [0, 0, 1]");
  return rotationQuaternion(angle * axis.normalized());
}

// a quaternion [w x y z] as written in a scene: normalized when its length is 1 to within
// kUnitQuaternionTolerance, refused otherwise (a typing mistake would silently rescale the body)
inline Quat unitQuaternion(double w, double x, double y, double z) {
  const Quat q(w, x, y, z);
  if (!q.coeffs().allFinite() || !(std::abs(q.norm() - 1.0) <= settings::kUnitQuaternionTolerance))
    throw std::invalid_argument("an orientation quaternion [w, x, y, z] must have unit length; this one has length " +
                                std::to_string(q.norm()) + " (divide it by its length, or write {axis: [x, y, z], angle: θ})");
  return q.normalized();
}

inline bool isFinite(const Vec3& v) { return v.allFinite(); }
inline bool isFinite(const Quat& q) { return q.coeffs().allFinite(); }

}  // namespace sim::world3d

#include "sim/world3d/body.h"

#include <Eigen/Eigenvalues>
#include <sstream>
#include <stdexcept>

namespace sim::world3d {

void Body::setMassProperties(double m, const Mat3& inertia) {
  if (!(m > 0.0) || !std::isfinite(m)) throw std::invalid_argument("mass must be a positive finite number");
  if (!inertia.allFinite()) throw std::invalid_argument("the inertia tensor must be finite");
  const double scale = inertia.cwiseAbs().maxCoeff();
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > settings::kInertiaSymmetryTolerance * scale)
    throw std::invalid_argument("the inertia tensor must be symmetric (I_ij = I_ji)");
  const Eigen::SelfAdjointEigenSolver<Mat3> principal(inertia);
  const Vec3 moments = principal.eigenvalues();  // ascending
  std::ostringstream values;
  values << '[' << moments.x() << ", " << moments.y() << ", " << moments.z() << ']';
  if (!(moments.x() > 0.0))
    throw std::invalid_argument("the inertia tensor's principal moments " + values.str() + " must be positive");
  if (moments.x() + moments.y() < (1.0 - settings::kInertiaTriangleTolerance) * moments.z())
    throw std::invalid_argument("the principal moments " + values.str() +
                                " break the triangle inequality I1 + I2 >= I3 that every solid satisfies");
  mass = m;
  invMass = 1.0 / m;
  inertiaBody = 0.5 * (inertia + inertia.transpose());
  invInertiaBody = inertiaBody.inverse();
  principalMoments = moments;
  principalAxes = principal.eigenvectors();
}

Mat3 Body::worldInertia(const Quat& at) const {
  const Mat3 r = rotationMatrix(at);
  return r * inertiaBody * r.transpose();
}

Mat3 Body::worldInverseInertia(const Quat& at) const {
  const Mat3 r = rotationMatrix(at);
  return r * invInertiaBody * r.transpose();
}

void Body::applyImpulse(const Vec3& r, const Vec3& j) {
  v += invMass * j;
  omega += worldInverseInertia() * (r - x).cross(j);
}

Body makeBody(const Shape& shape, double density) {
  const MassProperties p = massProperties(shape, density);
  return makeBody(shape, p.mass, p.inertia);
}

Body makeBody(const Shape& shape, double mass, const Mat3& inertiaBody) {
  Body b;
  b.shape = shape;
  b.setMassProperties(mass, inertiaBody);
  return b;
}

}  // namespace sim::world3d

#include "sim/world3d/collide3d.h"

namespace sim::world3d {

int planeContact(const Shape& shape, const BodyState& s, const Plane& plane, double margin,
                 ContactPoint3 out[kMaxContactPoints]) {
  const Mat3 r = s.rotation();
  // a surface point of the body, written with its signed distance above the plane
  int count = 0;
  auto consider = [&](const Vec3& bodyPoint, int feature) {
    const Vec3 p = s.x + r * bodyPoint;
    const double separation = plane.normal.dot(p - plane.point);
    if (separation > margin) return;
    ContactPoint3& c = out[count++];
    c = ContactPoint3{};
    c.point = p, c.separation = separation, c.feature = feature;
  };
  switch (shape.kind) {
    case ShapeKind::Box:
      // corner k has sign bits (x, y, z) = bits 0, 1, 2 of k
      for (int k = 0; k < 8; ++k)
        consider(0.5 * Vec3((k & 1) ? shape.sides.x() : -shape.sides.x(), (k & 2) ? shape.sides.y() : -shape.sides.y(),
                            (k & 4) ? shape.sides.z() : -shape.sides.z()),
                 k);
      break;
    case ShapeKind::Sphere: consider(-shape.radius * (r.transpose() * plane.normal), 0); break;
    case ShapeKind::Ellipsoid: {
      // the support point of x²/a² + y²/b² + z²/c² = 1 in direction d: A² d / |A d|
      const Vec3 d = -(r.transpose() * plane.normal);
      const Vec3 ad = shape.semiAxes.cwiseProduct(d);
      consider(shape.semiAxes.cwiseProduct(ad) / ad.norm(), 0);
      break;
    }
  }
  return count;
}

bool sphereContact(const BodyState& a, double ra, const BodyState& b, double rb, double margin, ContactPoint3& out,
                   Vec3& normal) {
  const Vec3 d = a.x - b.x;
  const double distance = d.norm();
  const double separation = distance - ra - rb;
  if (separation > margin) return false;
  // concentric spheres have no line of centers: push along z, as any direction would do
  normal = distance > 0.0 ? Vec3(d / distance) : Vec3::UnitZ();
  out = ContactPoint3{};
  out.point = b.x + (rb + 0.5 * separation) * normal;
  out.separation = separation;
  return true;
}

}  // namespace sim::world3d

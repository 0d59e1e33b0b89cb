#include "sim/world3d/impulse3d.h"

namespace sim::world3d {

PairInverses pairInverses(const Body& a, const Body* b) {
  return {a.worldInverseInertia(), b ? b->worldInverseInertia() : Mat3::Zero()};
}

Vec3 relativeVelocity(const Body& a, const Body* b, const Vec3& r) {
  return a.pointVelocity(r) - (b ? b->pointVelocity(r) : Vec3::Zero());
}

double inverseEffectiveMass(const Body& a, const Body* b, const PairInverses& inv, const Vec3& r, const Vec3& d) {
  const Vec3 ra = r - a.x;
  double k = a.invMass + d.dot((inv.a * ra.cross(d)).cross(ra));
  if (b) {
    const Vec3 rb = r - b->x;
    k += b->invMass + d.dot((inv.b * rb.cross(d)).cross(rb));
  }
  return k;
}

void applyImpulsePair(Body& a, Body* b, const Vec3& r, const Vec3& j) {
  a.applyImpulse(r, j);
  if (b) b->applyImpulse(r, -j);
}

ImpulseResult3 resolveImpact(Body& a, Body* b, const Vec3& r, const Vec3& n, double restitution, double friction) {
  const PairInverses inv = pairInverses(a, b);
  ImpulseResult3 out;
  const double vn = n.dot(relativeVelocity(a, b, r));
  if (vn < 0.0) {
    out.gamma = -(1.0 + restitution) * vn / inverseEffectiveMass(a, b, inv, r, n);
    applyImpulsePair(a, b, r, out.gamma * n);
  }
  if (friction <= 0.0 || out.gamma <= 0.0) return out;
  // the sliding left: the relative velocity in the contact's plane, stopped along its direction as
  // far as the cone allows
  const Vec3 v = relativeVelocity(a, b, r);
  const Vec3 slide = v - n.dot(v) * n;
  const double speed = slide.norm();
  if (speed == 0.0) return out;
  const Vec3 t = slide / speed;
  const double stop = speed / inverseEffectiveMass(a, b, inv, r, t);
  out.tangent = -std::min(stop, friction * out.gamma) * t;
  applyImpulsePair(a, b, r, out.tangent);
  return out;
}

}  // namespace sim::world3d

#include "sim/collision/impulse.h"

#include <algorithm>

namespace sim::collision {
using namespace sim::core;

double inverseEffectiveMass(const Body& a, const Body& b, const Vec2& r, const Vec2& n) {
  return inverseEffectiveMassAt(a, b, r - a.x, r - b.x, n);
}

void applyImpulsePair(Body& a, Body& b, const Vec2& r, const Vec2& j) {
  a.v += a.invMass * j;
  a.omega += a.invInertia * cross(r - a.x, j);
  b.v -= b.invMass * j;
  b.omega -= b.invInertia * cross(r - b.x, j);
}

NormalBlock normalBlock(const Body& a, const Body& b, const Vec2& r1, const Vec2& r2, const Vec2& n, double k11, double k22) {
  const double ra1 = cross(r1 - a.x, n), ra2 = cross(r2 - a.x, n);
  const double rb1 = cross(r1 - b.x, n), rb2 = cross(r2 - b.x, n);
  const double k12 = a.invMass + b.invMass + a.invInertia * ra1 * ra2 + b.invInertia * rb1 * rb2;
  return {k11, k12, k22, k11 * k22 - k12 * k12};
}

ImpulseResult resolveImpact(Body& a, Body& b, const Vec2& r, const Vec2& n, double restitution, double friction) {
  ImpulseResult out;
  const double vn = n.dot(relativeVelocity(a, b, r));
  const double k = inverseEffectiveMass(a, b, r, n);
  if (vn >= 0.0 || k == 0.0) return out;
  // the notes' last line writes m_eff⁻¹ where the effective mass belongs: divide by m_eff⁻¹
  out.gamma = -(1.0 + restitution) * vn / k;
  applyImpulsePair(a, b, r, out.gamma * n);
  if (friction > 0.0) {
    // Coulomb: the impulse that stops the sliding, or the most the cone allows
    const Vec2 t(-n.y(), n.x());
    const double vt = t.dot(relativeVelocity(a, b, r));
    const double kt = inverseEffectiveMass(a, b, r, t);
    out.tangent = std::clamp(-vt / kt, -friction * out.gamma, friction * out.gamma);
    applyImpulsePair(a, b, r, out.tangent * t);
  }
  return out;
}

}  // namespace sim::collision

// The notes' collision impulse ("Collisions: rigid body–obstacle", "Collisions: two rigid bodies").
//
// One formula serves both slides: an obstacle is a static body with m⁻¹ = I⁻¹ = 0, which turns
// the two-body effective mass into the body–obstacle one, m_eff = (m⁻¹ + (r′ × n̂)²/I)⁻¹.
#pragma once

#include <algorithm>

#include "sim/core/body.h"

namespace sim::collision {

// relative velocity of A's and B's material points at r: (v_a + ω_a × r_a) − (v_b + ω_b × r_b)
inline sim::core::Vec2 relativeVelocity(const sim::core::Body& a, const sim::core::Body& b, const sim::core::Vec2& r) {
  return a.pointVelocity(r) - b.pointVelocity(r);
}

// m_eff⁻¹ = m_a⁻¹ + m_b⁻¹ + (r_a × n̂)²/I_a + (r_b × n̂)²/I_b, for any direction n̂, from the lever
// arms r_a, r_b (centers of mass to the point) of any bodies with invMass and invInertia: a Body,
// or the solvers' compact copies of one
template <class A, class B>
double inverseEffectiveMassAt(const A& a, const B& b, const sim::core::Vec2& ra, const sim::core::Vec2& rb,
                              const sim::core::Vec2& n) {
  const double an = sim::core::cross(ra, n), bn = sim::core::cross(rb, n);
  return a.invMass + b.invMass + an * an * a.invInertia + bn * bn * b.invInertia;
}
// the same at world point r of two Bodies
double inverseEffectiveMass(const sim::core::Body& a, const sim::core::Body& b, const sim::core::Vec2& r,
                            const sim::core::Vec2& n);

// at a point with lever arms p.rA, p.rB, fixed within a step (the iterative solvers' points), for
// bodies with v, omega, invMass and invInertia:
// the velocity of A's point relative to B's, (v_a + ω_a × r_a) − (v_b + ω_b × r_b)
template <class Bd, class P>
sim::core::Vec2 relativeVelocityAt(const Bd& a, const Bd& b, const P& p) {
  return sim::core::Vec2(a.v + sim::core::cross(a.omega, p.rA)) - sim::core::Vec2(b.v + sim::core::cross(b.omega, p.rB));
}
// j to A and −j to B
template <class Bd, class P>
void applyAt(Bd& a, Bd& b, const P& p, const sim::core::Vec2& j) {
  a.v += a.invMass * j;
  a.omega += a.invInertia * sim::core::cross(p.rA, j);
  b.v -= b.invMass * j;
  b.omega -= b.invInertia * sim::core::cross(p.rB, j);
}

// Coulomb friction at the point, one Gauss–Seidel update along tangent t (Catto 2006): the
// accumulated tangent impulse p.tangentImpulse takes the increment that stops the sliding, clamped
// to ±μ times the point's accumulated normal impulse
template <class Bd, class P>
void solveFrictionAt(Bd& a, Bd& b, P& p, const sim::core::Vec2& t, double friction) {
  const double lambda = -p.tangentMass * t.dot(relativeVelocityAt(a, b, p));
  const double limit = friction * p.normalImpulse;
  const double total = std::clamp(p.tangentImpulse + lambda, -limit, limit);
  applyAt(a, b, p, (total - p.tangentImpulse) * t);
  p.tangentImpulse = total;
}

// j to A and −j to B at world point r
void applyImpulsePair(sim::core::Body& a, sim::core::Body& b, const sim::core::Vec2& r, const sim::core::Vec2& j);

// two contact points r1, r2 that share the normal n̂, solved together (Catto 2006; Box2D 2.4's
// block solver): normal impulses γ = (γ1, γ2) change the points' normal velocities by K γ, with
//   K_ii = m_eff⁻¹ at point i,
//   K_12 = m_a⁻¹ + m_b⁻¹ + (r_a1 × n̂)(r_a2 × n̂)/I_a + (r_b1 × n̂)(r_b2 × n̂)/I_b
struct NormalBlock {
  double k11 = 0.0, k12 = 0.0, k22 = 0.0;
  double det = 0.0;  // k11 k22 − k12²
  // the γ with K γ = d, by Cramer's rule; the caller checks that det is safely away from zero
  sim::core::Vec2 solve(double d1, double d2) const { return {(k22 * d1 - k12 * d2) / det, (k11 * d2 - k12 * d1) / det}; }
};
// K for the points r1, r2, with its diagonal as the caller holds it (the sequential solver keeps
// the effective masses, the event method the inverse ones)
NormalBlock normalBlock(const sim::core::Body& a, const sim::core::Body& b, const sim::core::Vec2& r1, const sim::core::Vec2& r2,
                        const sim::core::Vec2& n, double k11, double k22);

struct ImpulseResult {
  double gamma = 0.0;    // along n̂
  double tangent = 0.0;  // friction impulse along (−n_y, n_x)
};

// the notes' impulse for restitution c_r: γ = −(1 + c_r) v_n⁻ / m_eff⁻¹, so that v_n⁺ = −c_r v_n⁻;
// with friction μ > 0 a tangential impulse then stops the sliding, within Coulomb's cone |j_t| ≤ μγ
ImpulseResult resolveImpact(sim::core::Body& a, sim::core::Body& b, const sim::core::Vec2& r, const sim::core::Vec2& n,
                            double restitution, double friction);

}  // namespace sim::collision

// The notes' impulse in 3D (notes: "Collisions: rigid body–obstacle", "two rigid bodies", in vector
// form): at a world point r with normal n̂ from B to A,
//   v_n⁻ = n̂ · (v_a + ω_a × r_a − v_b − ω_b × r_b),   j = γ n̂,
//   γ = −(1 + c_r) v_n⁻ / (m_a⁻¹ + m_b⁻¹ + n̂ · (I_a⁻¹ (r_a × n̂)) × r_a + n̂ · (I_b⁻¹ (r_b × n̂)) × r_b),
// with I⁻¹ = R I_b⁻¹ Rᵀ the world inverse inertia (the slide's m_eff⁻¹ is the effective mass's
// inverse: this divides by it), so that v_n⁺ = −c_r v_n⁻. A plane is body B with no motion and zero
// inverses.
#pragma once

#include "sim/world3d/body.h"

namespace sim::world3d {

// the world inverse inertias of a pair, computed once per contact (B none: a plane)
struct PairInverses {
  Mat3 a = Mat3::Zero(), b = Mat3::Zero();
};
PairInverses pairInverses(const Body& a, const Body* b);

// v_a + ω_a × r_a − (v_b + ω_b × r_b): the velocity of A's material point at r relative to B's
Vec3 relativeVelocity(const Body& a, const Body* b, const Vec3& r);
// the inverse of the effective mass along the unit direction d at r: d · ((m_a⁻¹ + m_b⁻¹) d +
// (I_a⁻¹ (r_a × d)) × r_a + (I_b⁻¹ (r_b × d)) × r_b)
double inverseEffectiveMass(const Body& a, const Body* b, const PairInverses& inv, const Vec3& r, const Vec3& d);
// j to A at r, −j to B
void applyImpulsePair(Body& a, Body* b, const Vec3& r, const Vec3& j);

struct ImpulseResult3 {
  double gamma = 0.0;           // the normal impulse γ
  Vec3 tangent = Vec3::Zero();  // the friction impulse
};

// the notes' impulse for v_n⁺ = −c_r v_n⁻ at r, then Coulomb friction: the impulse in the contact's
// plane that stops the sliding left after it, held within the cone |j_t| ≤ μ γ (applied to both)
ImpulseResult3 resolveImpact(Body& a, Body* b, const Vec3& r, const Vec3& n, double restitution, double friction);

}  // namespace sim::world3d

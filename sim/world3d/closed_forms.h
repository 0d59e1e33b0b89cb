// Closed-form answers for free rigid bodies in 3D, independent of the simulator: what the tests,
// and later a scene's `expect`, compare a run against.
#pragma once

#include "sim/world3d/math.h"

namespace sim::world3d {

// K(k) = ∫₀^{π/2} dθ / √(1 − k² sin² θ), the complete elliptic integral of the first kind of
// modulus 0 ≤ k < 1, by the arithmetic–geometric mean: K = π / (2 AGM(1, k′)), k′ = √(1 − k²)
// (Abramowitz & Stegun, Handbook of Mathematical Functions, 17.6); infinite at k = 1
double completeEllipticK(double modulus);
// the same from the complementary modulus k′, which keeps its digits as k → 1
double completeEllipticKOfComplement(double complementaryModulus);

// a torque-free symmetric top: I₁ = I₂ about the body's x and y, I₃ about its symmetry axis z
// (Landau & Lifshitz, Mechanics, §33)
struct SymmetricTop {
  double transverse = 1.0;        // I₁ = I₂
  double axial = 1.0;             // I₃
  Vec3 omegaBody = Vec3::Zero();  // ω in body axes, at any instant
};
// the rate at which ω turns about the symmetry axis, seen from the body: Ω = ω₃ (I₃ − I₁) / I₁,
// rad/s, counter-clockwise about +z when positive (Euler's equations with I₁ = I₂)
double bodyPrecessionRate(const SymmetricTop& top);
// the rate at which the symmetry axis, and ω with it, turn about the fixed L in space:
// |L| / I₁, rad/s (Landau & Lifshitz §33)
double spacePrecessionRate(const SymmetricTop& top);
// the constant angle between ω and L, rad: the half-angle of the cone ω sweeps about L
double coneAngle(const SymmetricTop& top);
// the constant angle between the symmetry axis and L, rad: cos θ = I₃ ω₃ / |L|
double symmetryAxisAngle(const SymmetricTop& top);

// The period of ω_b's motion, s, for a free body with three distinct principal moments, energy E
// and |L| = M (Landau & Lifshitz, Mechanics, §37): with I₁ < I₂ < I₃ and M² > 2 E I₂,
//   T = 4 K(k) √(I₁ I₂ I₃ / ((I₃ − I₂)(M² − 2 E I₁))),
//   k² = (I₂ − I₁)(2 E I₃ − M²) / ((I₃ − I₂)(M² − 2 E I₁)),
//   k′² = 1 − k² = (I₃ − I₁)(M² − 2 E I₂) / ((I₃ − I₂)(M² − 2 E I₁)),
// and the same with I₁ and I₃ exchanged when M² < 2 E I₂; infinite on the separatrix M² = 2 E I₂.
// ω₂ ∝ sn changes sign twice a period: a body spun near its middle axis flips over every T/2.
// The moments may come in any order; two equal moments make a symmetric top (std::invalid_argument).
double flipPeriod(const Vec3& principalMoments, double energy, double angularMomentum);
// the same from ω in principal axes: M² − 2 E I_j = Σ_i I_i ω_i² (I_i − I_j) is then summed
// without the cancellation that M² and 2 E I₂ suffer near the middle axis
double flipPeriod(const Vec3& principalMoments, const Vec3& omegaPrincipal);

// the notes' impulse j at offset r′ = r − x from the center of a body of mass m and body inertia
// I_b at orientation q: v⁺ = v + j/m, ω⁺ = ω + I⁻¹ (r′ × j) with I = R I_b Rᵀ, and the kinetic
// energies ½ m v·v + ½ ω·I ω before and after (notes: "Impulses")
struct ImpulseOutcome {
  Vec3 velocity = Vec3::Zero();
  Vec3 angularVelocity = Vec3::Zero();
  double kineticEnergyBefore = 0.0;
  double kineticEnergyAfter = 0.0;
};
ImpulseOutcome afterImpulse(double mass, const Mat3& inertiaBody, const Quat& q, const Vec3& velocity,
                            const Vec3& angularVelocity, const Vec3& offset, const Vec3& impulse);

}  // namespace sim::world3d

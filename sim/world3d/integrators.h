// Fixed-step integrators of the 3D dynamics (dynamics.h) on (x, q, v, ω): the 2D world's four, with
// q advanced as a four-vector by q̇ = ½ (0, ω) q, and a splitting that moves q on the group of
// rotations, q ← exp(½ h ω) q, one file each, selectable by name.
#pragma once

#include "sim/core/enum_names.h"
#include "sim/world3d/dynamics.h"

namespace sim::world3d {

enum class Integrator { ExplicitEuler, SymplecticEuler, Midpoint, Rk4, Splitting };

// one step of size h, in place; a four-vector update leaves |q| off 1 by O(h²) per step, which
// normalizeRotations takes back (sim/README.md: Free rigid bodies in 3D, for what each keeps and loses)
void explicitEulerStep(const Dynamics& f, double h, States& y);  // order 1
// order 1; symplectic in x and v only: with q a four-vector and Euler's equations explicit, a free
// body's energy grows under it
void symplecticEulerStep(const Dynamics& f, double h, States& y);
void midpointStep(const Dynamics& f, double h, States& y);  // order 2
void rk4Step(const Dynamics& f, double h, States& y);       // order 4
// Dullweber–Leimkuhler–McLachlan's symmetric splitting, order 2 (splitting.cpp): kick, the free
// body's flow as rotations about the principal axes, kick; keeps |q| = 1 and, for a free body,
// L exactly
void splittingStep(const Dynamics& f, double h, States& y);
void integrate(Integrator method, const Dynamics& f, double h, States& y);

// how far one step moves a body under a constant acceleration a, beyond x + h v, in units of h² a
// (2D's constantAccelerationWeight): symplectic Euler 1, the midpoint rule, RK4 and the splitting
// (kick, drift, kick) ½, explicit Euler 0
double constantAccelerationWeight(Integrator method);

// q ← q / |q| for every body: the projection back onto unit quaternions after a step
void normalizeRotations(States& y);

// the order of the global error
int integratorOrder(Integrator method);

// names as written in scenes and on the command line: the 2D world's four, and splitting
inline constexpr sim::core::EnumNames<Integrator, 5> kIntegratorNames{{{
    {Integrator::ExplicitEuler, "explicit_euler"},
    {Integrator::SymplecticEuler, "symplectic_euler"},
    {Integrator::Midpoint, "midpoint"},
    {Integrator::Rk4, "rk4"},
    {Integrator::Splitting, "splitting"},
}}};

}  // namespace sim::world3d

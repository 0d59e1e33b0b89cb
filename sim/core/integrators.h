// Fixed-step time integrators of the free-body equations ẋ = v, θ̇ = ω, v̇ = f/m, ω̇ = τ/I.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "sim/core/body.h"
#include "sim/core/enum_names.h"

namespace sim::core {

enum class Integrator { ExplicitEuler, SymplecticEuler, Midpoint, Rk4 };

// time derivative of one body's state
struct BodyRate {
  Vec2 xDot = Vec2::Zero();
  double angleDot = 0.0;
  Vec2 vDot = Vec2::Zero();
  double omegaDot = 0.0;
};

using States = std::vector<BodyState>;
using Rates = std::vector<BodyRate>;

// what an integrator needs of the world: the state's time derivative at time t
class Dynamics {
 public:
  virtual ~Dynamics() = default;
  virtual void rates(double t, const States& y, Rates& out) const = 0;
};

// one step of size h from time t, in place
void explicitEulerStep(const Dynamics& f, double t, double h, States& y);
void symplecticEulerStep(const Dynamics& f, double t, double h, States& y);
void midpointStep(const Dynamics& f, double t, double h, States& y);
void rk4Step(const Dynamics& f, double t, double h, States& y);
void integrate(Integrator method, const Dynamics& f, double t, double h, States& y);

// how far one step moves a body under a constant acceleration a, beyond x + h v, in units of h² a:
// symplectic Euler 1 (x + h (v + h a)), the midpoint rule and RK4 1/2 (exact: x + h v + ½ h² a),
// explicit Euler 0 (x + h v). A contact solver's impulse over a step is such a force, P/h held
// for the step, so it moves the body by this times h Δv, as the integrator moves any other force
double constantAccelerationWeight(Integrator method);

// names as written in scenes and on the command line
inline constexpr EnumNames<Integrator, 4> kIntegratorNames{{{
    {Integrator::ExplicitEuler, "explicit_euler"},
    {Integrator::SymplecticEuler, "symplectic_euler"},
    {Integrator::Midpoint, "midpoint"},
    {Integrator::Rk4, "rk4"},
}}};
inline std::string_view integratorName(Integrator method) { return kIntegratorNames.name(method); }
inline std::optional<Integrator> integratorFromName(std::string_view name) { return kIntegratorNames.parse(name); }

}  // namespace sim::core

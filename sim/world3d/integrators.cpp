#include "sim/world3d/integrators.h"

#include <array>

namespace sim::world3d {

namespace {

// an explicit Runge–Kutta method by its Butcher tableau (Hairer, Nørsett & Wanner, Solving
// Ordinary Differential Equations I, §II.1): stage i is evaluated at y + h Σ_j a_ij k_j, the step
// is y + h Σ_i b_i k_i
struct Tableau {
  int stages;
  std::array<std::array<double, 4>, 4> a;
  std::array<double, 4> b;
};

constexpr Tableau kExplicitEuler{1, {}, {1.0}};
constexpr Tableau kMidpoint{2, {{{}, {0.5}}}, {0.0, 1.0}};
constexpr Tableau kRk4{4, {{{}, {0.5}, {0.0, 0.5}, {0.0, 0.0, 1.0}}}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};

// y + h Σ_j c_j k_j over the first `count` rates, body by body (q as a four-vector)
States combined(const States& y, double h, const std::array<Rates, 4>& k, const std::array<double, 4>& c, int count) {
  States out = y;
  for (int j = 0; j < count; ++j) {
    if (c[j] == 0.0) continue;
    for (size_t i = 0; i < y.size(); ++i) {
      const BodyRate& r = k[j][i];
      out[i].x += h * c[j] * r.xDot;
      out[i].q = plus(out[i].q, h * c[j], r.qDot);
      out[i].v += h * c[j] * r.vDot;
      out[i].omega += h * c[j] * r.omegaDot;
    }
  }
  return out;
}

void rungeKuttaStep(const Tableau& t, const Dynamics& f, double h, States& y) {
  std::array<Rates, 4> k;
  for (int i = 0; i < t.stages; ++i) f.rates(combined(y, h, k, t.a[i], i), k[i]);
  y = combined(y, h, k, t.b, t.stages);
}

}  // namespace

// y ← y + h f(y): first order; |q| grows by √(1 + (h|ω|/2)²) a step, energy grows
void explicitEulerStep(const Dynamics& f, double h, States& y) { rungeKuttaStep(kExplicitEuler, f, h, y); }

// the explicit midpoint rule: second order
void midpointStep(const Dynamics& f, double h, States& y) { rungeKuttaStep(kMidpoint, f, h, y); }

// classical Runge–Kutta: fourth order
void rk4Step(const Dynamics& f, double h, States& y) { rungeKuttaStep(kRk4, f, h, y); }

// velocities first, then positions with the new velocities: first order
void symplecticEulerStep(const Dynamics& f, double h, States& y) {
  Rates k;
  f.rates(y, k);
  for (size_t i = 0; i < y.size(); ++i) {
    BodyState& s = y[i];
    s.v += h * k[i].vDot;
    s.omega += h * k[i].omegaDot;
    s.x += h * s.v;
    s.q = plus(s.q, h, quaternionRate(s.q, s.omega));
  }
}

void integrate(Integrator method, const Dynamics& f, double h, States& y) {
  switch (method) {
    case Integrator::ExplicitEuler: return explicitEulerStep(f, h, y);
    case Integrator::SymplecticEuler: return symplecticEulerStep(f, h, y);
    case Integrator::Midpoint: return midpointStep(f, h, y);
    case Integrator::Rk4: return rk4Step(f, h, y);
    case Integrator::Splitting: return splittingStep(f, h, y);
  }
}

void normalizeRotations(States& y) {
  for (BodyState& s : y) s.q.normalize();
}

double constantAccelerationWeight(Integrator method) {
  switch (method) {
    case Integrator::ExplicitEuler: return 0.0;
    case Integrator::SymplecticEuler: return 1.0;
    case Integrator::Midpoint:
    case Integrator::Rk4:
    case Integrator::Splitting: return 0.5;
  }
  return 1.0;
}

int integratorOrder(Integrator method) {
  switch (method) {
    case Integrator::ExplicitEuler:
    case Integrator::SymplecticEuler: return 1;
    case Integrator::Midpoint:
    case Integrator::Splitting: return 2;
    case Integrator::Rk4: return 4;
  }
  return 0;
}

}  // namespace sim::world3d

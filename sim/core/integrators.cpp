#include "sim/core/integrators.h"

#include <array>

namespace sim::core {

namespace {

// y + h·k, body by body
States advanced(const States& y, double h, const Rates& k) {
  States out = y;
  for (size_t i = 0; i < y.size(); ++i) {
    out[i].x += h * k[i].xDot;
    out[i].angle += h * k[i].angleDot;
    out[i].v += h * k[i].vDot;
    out[i].omega += h * k[i].omegaDot;
  }
  return out;
}

}  // namespace

// y ← y + h f(y): first order, gains energy on oscillators
void explicitEulerStep(const Dynamics& f, double t, double h, States& y) {
  Rates k;
  f.rates(t, y, k);
  y = advanced(y, h, k);
}

// velocities first, then positions with the new velocities: first order, symplectic
void symplecticEulerStep(const Dynamics& f, double t, double h, States& y) {
  Rates k;
  f.rates(t, y, k);
  for (size_t i = 0; i < y.size(); ++i) {
    y[i].v += h * k[i].vDot;
    y[i].omega += h * k[i].omegaDot;
    y[i].x += h * y[i].v;
    y[i].angle += h * y[i].omega;
  }
}

// the explicit midpoint rule: second order
void midpointStep(const Dynamics& f, double t, double h, States& y) {
  Rates k1, k2;
  f.rates(t, y, k1);
  f.rates(t + 0.5 * h, advanced(y, 0.5 * h, k1), k2);
  y = advanced(y, h, k2);
}

// classical Runge–Kutta: fourth order
void rk4Step(const Dynamics& f, double t, double h, States& y) {
  Rates k1, k2, k3, k4;
  f.rates(t, y, k1);
  f.rates(t + 0.5 * h, advanced(y, 0.5 * h, k1), k2);
  f.rates(t + 0.5 * h, advanced(y, 0.5 * h, k2), k3);
  f.rates(t + h, advanced(y, h, k3), k4);
  for (size_t i = 0; i < y.size(); ++i) {
    const double w = h / 6.0;
    y[i].x += w * (k1[i].xDot + 2.0 * k2[i].xDot + 2.0 * k3[i].xDot + k4[i].xDot);
    y[i].angle += w * (k1[i].angleDot + 2.0 * k2[i].angleDot + 2.0 * k3[i].angleDot + k4[i].angleDot);
    y[i].v += w * (k1[i].vDot + 2.0 * k2[i].vDot + 2.0 * k3[i].vDot + k4[i].vDot);
    y[i].omega += w * (k1[i].omegaDot + 2.0 * k2[i].omegaDot + 2.0 * k3[i].omegaDot + k4[i].omegaDot);
  }
}

void integrate(Integrator method, const Dynamics& f, double t, double h, States& y) {
  switch (method) {
    case Integrator::ExplicitEuler: return explicitEulerStep(f, t, h, y);
    case Integrator::SymplecticEuler: return symplecticEulerStep(f, t, h, y);
    case Integrator::Midpoint: return midpointStep(f, t, h, y);
    case Integrator::Rk4: return rk4Step(f, t, h, y);
  }
}

double constantAccelerationWeight(Integrator method) {
  switch (method) {
    case Integrator::ExplicitEuler: return 0.0;
    case Integrator::SymplecticEuler: return 1.0;
    case Integrator::Midpoint:
    case Integrator::Rk4: return 0.5;
  }
  return 1.0;
}

}  // namespace sim::core

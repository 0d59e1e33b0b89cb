#include "sim/world3d/dynamics.h"

#include <doctest/doctest.h>

using namespace sim::world3d;

namespace {

// a tilted, spinning body of three distinct moments under gravity and a point force
struct Torqued {
  std::vector<Body> bodies;
  ForceSet forces;
  Torqued() {
    Body b = makeBody(makeBox(Vec3(0.2, 0.4, 0.6)), 2.0, Vec3(0.3, 0.5, 0.6).asDiagonal());
    b.q = axisAngle(Vec3(1, 1, 0), 0.4);
    b.v = Vec3(0.1, 0, 0);
    b.omega = Vec3(1.0, 2.0, 3.0);
    bodies.push_back(b);
    forces.gravity = Vec3(0, 0, -9.81);
    forces.pointForces.push_back({0, Vec3(0.1, 0.2, 0.3), Vec3(1, -2, 0.5)});
  }
};

Vec3 momentum(const Body& b, const BodyState& s) { return b.worldInertia(s.q) * s.omega; }

}  // namespace

TEST_CASE("the rates are the notes' ẋ = v, q̇ = ½ (0, ω) q, v̇ = f/m") {
  const Torqued w;
  const States y(w.bodies.begin(), w.bodies.end());
  Rates k;
  Dynamics{w.bodies, w.forces, 0.0}.rates(y, k);
  CHECK(k[0].xDot == y[0].v);
  CHECK(k[0].qDot.coeffs().isApprox(quaternionRate(y[0].q, y[0].omega).coeffs(), 1e-15));
  CHECK(k[0].vDot.isApprox(Vec3(1, -2, 0.5) / 2.0 + Vec3(0, 0, -9.81), 1e-15));
}

TEST_CASE("ω̇ solves Euler's equations in body axes: I₁ ω̇₁ = (I₂ − I₃) ω₂ ω₃ + τ₁ and so on") {
  const Torqued w;
  const Body& b = w.bodies[0];
  const Vec3 torque(0.3, -0.1, 0.2);
  const Mat3 r = rotationMatrix(b.q);
  const Vec3 wb = r.transpose() * b.omega, tb = r.transpose() * torque;
  const double i1 = 0.3, i2 = 0.5, i3 = 0.6;
  const Vec3 expected((i2 - i3) * wb.y() * wb.z() + tb.x(), (i3 - i1) * wb.z() * wb.x() + tb.y(),
                      (i1 - i2) * wb.x() * wb.y() + tb.z());
  const Vec3 omegaDotBody = r.transpose() * angularAcceleration(b, b.q, b.omega, torque);
  CHECK(Vec3(i1, i2, i3).cwiseProduct(omegaDotBody).isApprox(expected, 1e-14));
}

TEST_CASE("along the rates, dL/dt = τ in the world frame and dE/dt = f·v + τ·ω") {
  const Torqued w;
  const Dynamics f{w.bodies, w.forces, 0.0};
  const States y(w.bodies.begin(), w.bodies.end());
  Rates k;
  f.rates(y, k);
  Wrenches wrench;
  f.wrenches(y, wrench);
  // move along the rates by ±e: a central difference of L(y) and of the kinetic energy
  const double e = 1e-6;
  auto moved = [&](double s) {
    BodyState m = y[0];
    m.x += s * k[0].xDot, m.q = plus(m.q, s, k[0].qDot), m.v += s * k[0].vDot, m.omega += s * k[0].omegaDot;
    return m;
  };
  const Body& b = w.bodies[0];
  const Vec3 lDot = (momentum(b, moved(e)) - momentum(b, moved(-e))) / (2 * e);
  CHECK((lDot - wrench[0].torque).norm() < 1e-8);
  auto kinetic = [&](const BodyState& s) { return 0.5 * b.mass * s.v.squaredNorm() + 0.5 * s.omega.dot(momentum(b, s)); };
  const double power = (kinetic(moved(e)) - kinetic(moved(-e))) / (2 * e);
  CHECK(std::abs(power - (wrench[0].force.dot(y[0].v) + wrench[0].torque.dot(y[0].omega))) < 1e-8);
}

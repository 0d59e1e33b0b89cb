#include "sim/world3d/diagnostics.h"

#include <doctest/doctest.h>

#include "support/world3d_fixtures.h"
#include "support/redefined.h"

using namespace sim::world3d;
using fixtures3d::relativeError;

TEST_CASE("kinetic energy ½ m v·v + ½ ω·L, and a sphere's ½ (⅖ m r²) ω²") {
  World w;
  Body ball = makeBody(makeSphere(0.5), 6.0 / (4.0 / 3.0 * std::numbers::pi * 0.125));  // 6 kg
  ball.v = Vec3(1, 2, 2);
  ball.omega = Vec3(0, 3, 4);
  w.bodies.push_back(ball);
  const KineticEnergy k = kineticEnergy(w.bodies[0]);
  CHECK(relativeError(k.translational, 0.5 * 6 * 9) < 1e-15);
  CHECK(relativeError(k.rotational, 0.5 * 0.4 * 6 * 0.25 * 25) < 1e-14);
  w = fixtures::redefined(w, [&](auto& d) { d.forces.gravity = Vec3(0, 0, -10); });
  w.bodies[0].x = Vec3(0, 0, 2);
  CHECK(relativeError(energy(w).potential, 6 * 10 * 2) < 1e-15);
  CHECK(relativeError(energy(w).total(), k.total() + 120) < 1e-15);
}

TEST_CASE("angular momentum about the origin: Σ x × m v + I ω; linear momentum Σ m v") {
  World w = fixtures3d::springChain(Integrator::Rk4, 0.01);
  w.bodies[1].v = Vec3(0, 0.5, 0);
  Vec3 l = Vec3::Zero(), p = Vec3::Zero();
  for (const Body& b : w.bodies) {
    l += b.mass * b.x.cross(b.v) + b.worldInertia() * b.omega;
    p += b.mass * b.v;
  }
  CHECK(angularMomentum(w).isApprox(l, 1e-15));
  CHECK(linearMomentum(w).isApprox(p, 1e-15));
  // the orbital part alone: a body passing the origin at distance d, speed s, has |L| = m d s
  World passing;
  Body b = makeBody(makeSphere(0.1), 1.0);
  b.x = Vec3(0, 3, 0);
  b.v = Vec3(2, 0, 0);
  passing.bodies.push_back(b);
  CHECK(angularMomentum(passing).isApprox(Vec3(0, 0, -b.mass * 3 * 2), 1e-15));
}

TEST_CASE("quaternion drift: the largest | |q| − 1 |") {
  World w = fixtures3d::springChain(Integrator::Rk4, 0.01);
  CHECK(quaternionDrift(w) < 1e-15);
  w.bodies[1].q = Quat(1.001 * w.bodies[1].q.coeffs());
  CHECK(std::abs(quaternionDrift(w) - 0.001) < 1e-12);
}

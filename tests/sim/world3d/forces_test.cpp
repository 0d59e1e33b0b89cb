#include "sim/world3d/forces.h"

#include <doctest/doctest.h>

#include "support/world3d_fixtures.h"

using namespace sim::world3d;
using fixtures3d::relativeError;

namespace {

Wrenches at(const ForceSet& forces, const std::vector<Body>& bodies, double window = 0.0) {
  Wrenches w;
  forces.accumulate(window, bodies, std::vector<BodyState>(bodies.begin(), bodies.end()), w);
  return w;
}

std::vector<Body> twoBodies() {
  Body a = makeBody(makeBox(Vec3(0.2, 0.4, 0.6)), 10.0), b = makeBody(makeEllipsoid(Vec3(0.1, 0.2, 0.3)), 30.0);
  a.x = Vec3(0.1, 0.2, 0.3);
  a.q = axisAngle(Vec3(1, -1, 2), 0.7);
  a.v = Vec3(0.3, 0, 0.1);
  a.omega = Vec3(1, 2, -1);
  b.x = Vec3(-0.5, 1.0, -0.2);
  b.q = axisAngle(Vec3(0, 1, 1), -1.1);
  b.v = Vec3(0, -0.4, 0.2);
  b.omega = Vec3(-2, 0.5, 0.3);
  return {a, b};
}

}  // namespace

TEST_CASE("a point force gives f and τ = r′ × f; a body-frame force turns with the body") {
  std::vector<Body> bodies = twoBodies();
  const Vec3 rb(0.1, -0.2, 0.3), f(0, 0, 5);
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, -1, 2).normalized()).toRotationMatrix();  // independent R
  ForceSet forces;
  forces.pointForces.push_back({0, rb, f});
  Wrenches w = at(forces, bodies);
  CHECK(w[0].force.isApprox(f, 1e-15));
  CHECK(w[0].torque.isApprox((r * rb).cross(f), 1e-14));
  CHECK(w[1].force.isZero());

  forces.pointForces[0].bodyFrame = true;
  w = at(forces, bodies);
  CHECK(w[0].force.isApprox(r * f, 1e-14));
  CHECK(w[0].torque.isApprox((r * rb).cross(r * f), 1e-14));
  // through the center: no torque
  forces.pointForces[0].point.setZero();
  CHECK(at(forces, bodies)[0].torque.norm() < 1e-15);
}

TEST_CASE("a timed force is on during [from, until), and the step is split at both") {
  std::vector<Body> bodies = twoBodies();
  ForceSet forces;
  forces.pointForces.push_back({1, Vec3::Zero(), Vec3(1, 0, 0), false, 0.25, 0.5});
  CHECK(at(forces, bodies, 0.2)[1].force.isZero());
  CHECK(at(forces, bodies, 0.25)[1].force.x() == 1.0);
  CHECK(at(forces, bodies, 0.4999)[1].force.x() == 1.0);
  CHECK(at(forces, bodies, 0.5)[1].force.isZero());
  CHECK(forces.breakpoints() == std::vector<double>{0.25, 0.5});
}

TEST_CASE("springs: Hooke's law along the spring, equal and opposite, no net torque about the origin") {
  std::vector<Body> bodies = twoBodies();
  ForceSet forces;
  const Vec3 pa(0.1, 0.2, 0.3), pb(0, 0, 0.3);
  forces.springs.push_back({0, pa, 1, pb, 40.0, 0.5, 0.0});
  const Wrenches w = at(forces, bodies);
  const Vec3 a = bodies[0].toWorld(pa), b = bodies[1].toWorld(pb);
  const Vec3 expected = 40.0 * ((b - a).norm() - 0.5) * (b - a).normalized();
  CHECK(w[0].force.isApprox(expected, 1e-14));
  CHECK(w[1].force.isApprox(-expected, 1e-14));
  CHECK(w[0].torque.isApprox((a - bodies[0].x).cross(expected), 1e-14));
  const Vec3 total = bodies[0].x.cross(w[0].force) + w[0].torque + bodies[1].x.cross(w[1].force) + w[1].torque;
  CHECK(total.norm() < 1e-13);
}

TEST_CASE("spring damping pulls against the stretch rate, drag against v and ω") {
  std::vector<Body> bodies = twoBodies();
  for (Body& b : bodies) b.omega.setZero(), b.v.setZero();
  bodies[1].x = bodies[0].x + Vec3(0, 0, 2);
  bodies[1].v = Vec3(0, 0, 0.5);  // moving away along the spring at 0.5 m/s
  ForceSet forces;
  forces.springs.push_back({0, Vec3::Zero(), 1, Vec3::Zero(), 0.0, 2.0, 3.0});
  CHECK(forces.dependsOnVelocity());
  Wrenches w = at(forces, bodies);
  CHECK(w[0].force.isApprox(Vec3(0, 0, 1.5), 1e-15));  // B runs away: A is pulled after it
  CHECK(w[1].force.isApprox(Vec3(0, 0, -1.5), 1e-15));

  ForceSet drag;
  CHECK(!drag.dependsOnVelocity());
  bodies = twoBodies();
  drag.drags.push_back({1, 0.3, 0.2});
  w = at(drag, bodies);
  CHECK(w[1].force.isApprox(-0.3 * bodies[1].v, 1e-15));
  CHECK(w[1].torque.isApprox(-0.2 * bodies[1].omega, 1e-15));
}

TEST_CASE("the potential energy's gradient is minus the force, and its rate under a rotation minus the torque") {
  std::vector<Body> bodies = twoBodies();
  ForceSet forces;
  forces.gravity = Vec3(0.5, 0, -9.81);
  forces.springs.push_back({0, Vec3(0.1, 0.2, 0.3), sim::core::kWorldAnchor, Vec3(1, 1, 1), 30.0, 0.4, 0.0});
  forces.springs.push_back({0, Vec3(-0.1, 0.2, -0.3), 1, Vec3(0, 0, 0.3), 40.0, 0.5, 0.0});
  const Wrenches w = at(forces, bodies);
  const double e = 1e-6;
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k) {
      CAPTURE(i);
      CAPTURE(k);
      const Vec3 step = e * Vec3::Unit(k);
      std::vector<Body> plus = bodies, minus = bodies;
      plus[i].x += step, minus[i].x -= step;
      const double dV = (forces.potentialEnergy(plus) - forces.potentialEnergy(minus)) / (2 * e);
      CHECK(std::abs(-dV - w[i].force[k]) < 1e-6);
      // turning body i about world axis k by ±e: dV/dθ = −τ_k
      plus = bodies, minus = bodies;
      plus[i].q = rotationQuaternion(step) * bodies[i].q, minus[i].q = rotationQuaternion(-step) * bodies[i].q;
      const double dVdTheta = (forces.potentialEnergy(plus) - forces.potentialEnergy(minus)) / (2 * e);
      CHECK(std::abs(-dVdTheta - w[i].torque[k]) < 1e-6);
    }
  // the gravity part on its own: −m g·x
  ForceSet gravity;
  gravity.gravity = forces.gravity;
  CHECK(relativeError(gravity.potentialEnergy(bodies),
                      -(bodies[0].mass * bodies[0].x + bodies[1].mass * bodies[1].x).dot(forces.gravity)) < 1e-14);
}

#include "sim/core/forces.h"

#include <doctest/doctest.h>

#include "sim/world/diagnostics.h"

using sim::core::Vec2;

namespace {

sim::core::Body body(double mass, double inertia, Vec2 x, double angle) {
  sim::core::Body b;
  b.shape = sim::core::makeBox(1, 1);
  b.mass = mass, b.invMass = 1 / mass, b.inertia = inertia, b.invInertia = 1 / inertia;
  b.setState({x, angle, Vec2::Zero(), 0.0});
  return b;
}

}  // namespace

TEST_CASE("a point force gives f and τ = r′ × f, in the world or the body frame") {
  std::vector<sim::core::Body> bodies{body(2, 1, {1, 1}, std::numbers::pi / 2)};
  std::vector<sim::core::BodyState> states{bodies[0].state()};
  sim::core::ForceSet fs;
  fs.pointForces.push_back({0, {0, 2}, {1, 0}, false, 0.0, 1.0});
  std::vector<Vec2> f;
  std::vector<double> tau;
  fs.accumulate(0.5, bodies, states, f, tau);
  // the body point (0, 2) turned by 90° sits at r′ = (-2, 0): τ = (-2, 0) × (1, 0) = 0
  CHECK((f[0] - Vec2(1, 0)).norm() < 1e-15);
  CHECK(tau[0] == doctest::Approx(0.0));

  fs.pointForces[0].bodyFrame = true;  // (1, 0) in the body is (0, 1) in the world
  fs.accumulate(0.5, bodies, states, f, tau);
  CHECK((f[0] - Vec2(0, 1)).norm() < 1e-15);
  CHECK(tau[0] == doctest::Approx(-2.0));

  // off outside [from, until)
  fs.accumulate(1.0, bodies, states, f, tau);
  CHECK(f[0].norm() == 0.0);
}

TEST_CASE("spring forces are minus the gradient of the spring potential, and opposite on two bodies") {
  std::vector<sim::core::Body> bodies{body(1, 0.1, {0.3, -1.2}, 0.4), body(2, 0.3, {1.5, 0.2}, -0.2)};
  sim::core::ForceSet fs;
  fs.springs.push_back({0, {0, 0.5}, 1, {0.1, -0.2}, 40, 0.5, 0});
  std::vector<sim::core::BodyState> states{bodies[0].state(), bodies[1].state()};
  std::vector<Vec2> f;
  std::vector<double> tau;
  fs.accumulate(0.0, bodies, states, f, tau);
  CHECK((f[0] + f[1]).norm() < 1e-12);

  // central differences of the potential in x, y and the angle of body 0
  const double h = 1e-6;
  auto potentialWith = [&](Vec2 dx, double da) {
    std::vector<sim::core::Body> moved = bodies;
    moved[0].setState({bodies[0].x + dx, bodies[0].angle + da, Vec2::Zero(), 0.0});
    return fs.potentialEnergy(moved);
  };
  const double fx = -(potentialWith({h, 0}, 0) - potentialWith({-h, 0}, 0)) / (2 * h);
  const double fy = -(potentialWith({0, h}, 0) - potentialWith({0, -h}, 0)) / (2 * h);
  const double t = -(potentialWith({0, 0}, h) - potentialWith({0, 0}, -h)) / (2 * h);
  CHECK(f[0].x() == doctest::Approx(fx).epsilon(1e-7));
  CHECK(f[0].y() == doctest::Approx(fy).epsilon(1e-7));
  CHECK(tau[0] == doctest::Approx(t).epsilon(1e-7));
}

TEST_CASE("spring damping opposes the stretch rate; drag opposes v and ω") {
  std::vector<sim::core::Body> bodies{body(1, 1, {0, -1}, 0)};
  std::vector<sim::core::BodyState> states{{{0, -1}, 0.0, {0, -2}, 3.0}};
  sim::core::ForceSet fs;
  fs.springs.push_back({0, {0, 0}, sim::core::kWorldAnchor, {0, 0}, 0, 1, 0.5});
  fs.drags.push_back({0, 0.25, 0.1});
  std::vector<Vec2> f;
  std::vector<double> tau;
  fs.accumulate(0, bodies, states, f, tau);
  // moving away from the anchor at 2 m/s: damping pulls back with 0.5·2, drag with 0.25·2
  CHECK((f[0] - Vec2(0, 1.0 + 0.5)).norm() < 1e-15);
  CHECK(tau[0] == doctest::Approx(-0.3));
}

TEST_CASE("gravity acts at the center of mass and its potential is -m g·x") {
  std::vector<sim::core::Body> bodies{body(3, 1, {2, 5}, 1.0)};
  sim::core::ForceSet fs;
  fs.gravity = {0, -10};
  std::vector<sim::core::BodyState> states{bodies[0].state()};
  std::vector<Vec2> f;
  std::vector<double> tau;
  fs.accumulate(0, bodies, states, f, tau);
  CHECK((f[0] - Vec2(0, -30)).norm() == 0.0);
  CHECK(tau[0] == 0.0);
  CHECK(fs.potentialEnergy(bodies) == doctest::Approx(150.0));
}

#include "sim/core/integrators.h"

#include <doctest/doctest.h>

#include <cmath>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/yaml/scene_yaml.h"

namespace {

// a spinning box thrown under gravity (g = 9.81)
const char* kProjectile = R"(
duration: 2
world: {gravity: [0, -9.81]}
bodies:
  - {name: box, shape: {box: [0.5, 0.25]}, density: 8, position: [0, 1], angle: 0.3, velocity: [3, 8], angular_velocity: 5}
)";

// a bar hung by one end from a spring, released tilted: translation and rotation are coupled
const char* kSpringBar = R"(
duration: 1
world: {gravity: [0, -9.81]}
bodies:
  - {name: bar, shape: {box: [0.1, 1.0]}, mass: 1, position: [0.3, -1.2], angle: 0.4}
forces:
  - {type: spring, body: bar, point: [0, 0.5], anchor: [0, 0], stiffness: 40, rest_length: 0.5}
)";

sim::world::World run(const char* yaml, sim::core::Integrator method, double dt, double until) {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(yaml, "inline.yaml");
  def.integrator = method;
  def.dt = dt;
  sim::world::World w = sim::scene::buildWorld(def);
  w.advanceTo(until);
  return w;
}

// distance in the state space of the bar (position, angle, velocity, angular velocity)
double stateError(const sim::core::Body& a, const sim::core::Body& b) {
  return std::sqrt((a.x - b.x).squaredNorm() + std::pow(a.angle - b.angle, 2) + (a.v - b.v).squaredNorm() +
                   std::pow(a.omega - b.omega, 2));
}

constexpr sim::core::Integrator kAll[] = {sim::core::Integrator::ExplicitEuler, sim::core::Integrator::SymplecticEuler,
                                          sim::core::Integrator::Midpoint, sim::core::Integrator::Rk4};

}  // namespace

TEST_CASE("projectile: explicit Euler is high by g·h·t/2, symplectic Euler low by it, midpoint and RK4 exact") {
  const double g = 9.81, h = 0.01, t = 2.0;
  const double exactY = 1 + 8 * t - 0.5 * g * t * t;
  const double roundOff = 1e-12;
  CHECK(run(kProjectile, sim::core::Integrator::ExplicitEuler, h, t).bodies[0].x.y() - exactY ==
        doctest::Approx(g * h * t / 2).epsilon(roundOff / (g * h * t / 2)));
  CHECK(run(kProjectile, sim::core::Integrator::SymplecticEuler, h, t).bodies[0].x.y() - exactY ==
        doctest::Approx(-g * h * t / 2).epsilon(roundOff / (g * h * t / 2)));
  CHECK(std::abs(run(kProjectile, sim::core::Integrator::Midpoint, h, t).bodies[0].x.y() - exactY) < roundOff);
  CHECK(std::abs(run(kProjectile, sim::core::Integrator::Rk4, h, t).bodies[0].x.y() - exactY) < roundOff);
  for (sim::core::Integrator m : kAll) {
    const sim::world::World w = run(kProjectile, m, h, t);
    // horizontal motion and the velocity are linear in t: exact for every method
    CHECK(std::abs(w.bodies[0].x.x() - 3 * t) < roundOff);
    CHECK(std::abs(w.bodies[0].v.y() - (8 - g * t)) < roundOff);
  }
}

TEST_CASE("rotation at constant ω is exact for every method, and q stays unit length") {
  for (sim::core::Integrator m : kAll) {
    CAPTURE(sim::core::integratorName(m));
    const sim::world::World w = run(kProjectile, m, 0.013, 2.0);
    const sim::core::Body& b = w.bodies[0];
    CHECK(std::abs(b.angle - (0.3 + 5 * 2.0)) < 1e-12);
    CHECK(std::abs(b.q().c - std::cos(0.3 + 5 * 2.0)) < 1e-12);
    CHECK(std::abs(b.q().s - std::sin(0.3 + 5 * 2.0)) < 1e-12);
    CHECK(std::abs(b.q().c * b.q().c + b.q().s * b.q().s - 1) < 1e-15);
  }
}

TEST_CASE("spring bar: measured convergence orders are 1, 1, 2, 4 (±0.3)") {
  const double until = 1.0;
  const sim::world::World reference = run(kSpringBar, sim::core::Integrator::Rk4, 1.0 / 12800, until);
  struct Case {
    sim::core::Integrator method;
    double h;
    double order;
  };
  // steps in each method's asymptotic range, well above the reference's and round-off's error
  for (const Case& c :
       {Case{sim::core::Integrator::ExplicitEuler, 1e-3, 1}, Case{sim::core::Integrator::SymplecticEuler, 1e-3, 1},
        Case{sim::core::Integrator::Midpoint, 4e-3, 2}, Case{sim::core::Integrator::Rk4, 2e-2, 4}}) {
    CAPTURE(sim::core::integratorName(c.method));
    const double coarse = stateError(run(kSpringBar, c.method, c.h, until).bodies[0], reference.bodies[0]);
    const double fine = stateError(run(kSpringBar, c.method, c.h / 2, until).bodies[0], reference.bodies[0]);
    const double measured = std::log2(coarse / fine);
    MESSAGE(sim::core::integratorName(c.method), ": error ", coarse, " -> ", fine, ", order ", measured);
    CHECK(measured == doctest::Approx(c.order).epsilon(0.3 / c.order));
  }
}

TEST_CASE("spring bar over 1000 periods: explicit Euler's energy grows, symplectic Euler's stays bounded") {
  // vertical period 2π/√(k/m) ≈ 0.99 s
  const double periods = 1000, h = 2e-3;
  const double duration = periods * 2 * std::numbers::pi / std::sqrt(40.0);
  auto energyHistory = [&](sim::core::Integrator m) {
    sim::scene::SceneDef def = sim::yaml::loadSceneText(kSpringBar, "inline.yaml");
    def.integrator = m;
    def.dt = h;
    sim::world::World w = sim::scene::buildWorld(def);
    std::vector<double> e{sim::world::energy(w).total()};
    for (int k = 1; k <= 100; ++k) {
      w.advanceTo(duration * k / 100);
      e.push_back(sim::world::energy(w).total());
    }
    return e;
  };
  const std::vector<double> symplectic = energyHistory(sim::core::Integrator::SymplecticEuler);
  const double e0 = symplectic[0];
  double swing = 0;
  for (double e : symplectic) swing = std::max(swing, std::abs(e - e0));
  // bounded: within 2 % of the energy scale throughout
  CHECK(swing < 0.02 * std::abs(e0));

  const std::vector<double> explicitEuler = energyHistory(sim::core::Integrator::ExplicitEuler);
  // grows: every tenth of the run ends with more energy than the one before, far above the start
  for (size_t k = 10; k < explicitEuler.size(); k += 10) CHECK(explicitEuler[k] > explicitEuler[k - 10]);
  CHECK(explicitEuler.back() - e0 > 100 * std::abs(e0));
}

TEST_CASE("integrators are selected by their scene names") {
  for (sim::core::Integrator m : kAll) CHECK(sim::core::integratorFromName(sim::core::integratorName(m)) == m);
  CHECK_FALSE(sim::core::integratorFromName("euler").has_value());
}

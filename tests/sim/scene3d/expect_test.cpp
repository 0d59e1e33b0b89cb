// A 3D scene's `expect` entries: the state at an instant (orientation up to its sign), energies and
// momenta, and what the run measures against the free body's closed forms (precession rates, the
// flip period); a wrong answer fails, and a period that the run cannot measure says why.
#include "sim/scene3d/expect.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/scene3d/scene_build.h"
#include "sim/world3d/closed_forms.h"
#include "sim/yaml3d/scene_yaml.h"

using namespace sim::scene3d;
using namespace sim::world3d;
using sim::core::CheckResult;

namespace {

SceneDef load(const std::string& text) { return sim::yaml3d::loadSceneText(text, "inline.yaml"); }

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// the one result of a scene's expect entries
CheckResult only(const std::vector<CheckResult>& results) {
  REQUIRE(results.size() == 1);
  return results.front();
}

}  // namespace

TEST_CASE("the notes' poll in 3D: Δv = j/m, Δω = I⁻¹ (r′ × j) and the kinetic energy after, to round-off") {
  // the bar l = 4 along z, m = 3, I = 4 about x and y; j = (1, 0, 0) at its end (0, 0, 2) at t = 0.5
  const std::string scene = R"(
dimensions: 3
duration: 1
sim: {integrator: rk4}
bodies:
  - {name: bar, shape: {box: [0.2, 0.2, 4]}, mass: 3, inertia: [4, 4, 0.1]}
events:
  - {time: 0.5, body: bar, impulse: [1, 0, 0], point: [0, 0, 2]}
expect:
  - {time: 0.5, body: bar, velocity: [0.333333333333333333, 0, 0], angular_velocity: [0, 0.5, 0], kinetic_energy: 0.666666666666666667, tolerance: 1e-15}
  - {time: 1, body: bar, angular_momentum: [0, 2, 0], position: [0.166666666666666667, 0, 0], tolerance: 1e-14}
  - {time: 1, momentum: [1, 0, 0], angular_momentum: [0, 2, 0], total_energy: 0.666666666666666667, tolerance: 1e-14}
)";
  const std::vector<CheckResult> results = runExpects(load(scene));
  REQUIRE(results.size() == 8);
  for (const CheckResult& r : results) {
    CAPTURE(r.quantity);
    CHECK(r.passed());
  }
  CHECK(results[1].quantity == "bar.angular_velocity");
  CHECK(results[1].actual == std::vector<double>{0, 0.5, 0});
  // the same entry with a wrong answer fails
  std::string wrong = scene;
  wrong.replace(wrong.find("[0, 0.5, 0]"), 11, "[0, 0.6, 0]");
  CHECK_FALSE(runExpects(load(wrong))[1].passed());
}

TEST_CASE("an orientation is compared with the nearer of q and −q, which turn the body alike") {
  const std::string scene = R"(
dimensions: 3
sim: {integrator: rk4, dt: 0.01}
bodies:
  - {name: a, shape: {box: [1, 2, 3]}, angular_velocity: [0, 0, 1]}
expect:
  - {time: 1, body: a, orientation: [-0.87758256189037276, 0, 0, -0.47942553860420301], tolerance: 1e-9}
  - {time: 1, body: a, orientation: [0.87758256189037276, 0, 0, 0.47942553860420301], quaternion_norm: 1, tolerance: 1e-9}
)";
  const std::vector<CheckResult> results = runExpects(load(scene));
  REQUIRE(results.size() == 3);
  for (const CheckResult& r : results) CHECK(r.passed());
  // reported with the expected one's sign
  CHECK(results[0].actual[0] < 0.0);
  CHECK(results[1].actual[0] > 0.0);
}

TEST_CASE("the flip period measured from the run against K(k), and a run too short to measure one") {
  // a box of sides 0.1 × 0.4 × 0.8 spun about its middle axis y at 4 rad/s, nudged about x and z
  const std::string body = R"(
dimensions: 3
duration: 8
sim: {integrator: rk4, dt: 0.001}
bodies:
  - {name: box, shape: {box: [0.1, 0.4, 0.8]}, density: 31.25, angular_velocity: [0.1, 4, 0.1]}
)";
  const World w = buildWorld(load(body));
  const double period = sim::world3d::flipPeriod(w.bodies[0].inertiaBody.diagonal(), w.bodies[0].omega);
  MESSAGE("closed form: flips every ", period / 2, " s");
  const CheckResult r = only(runExpects(load(body + "expect:\n  - {time: 8, body: box, flip_period: " + num(period) + "}\n")));
  MESSAGE("measured over 8 s: ", r.actual[0], " s, error ", r.error, " s");
  // RK4 at dt = 0.001 and the crossings on Hermite's cubic: far below the straight line's 1e-7
  CHECK(r.error < 1e-8 * period);
  // one flip by t = 2: no period yet, and the quantity says why
  const CheckResult early =
      only(runExpects(load(body + "expect:\n  - {time: 2, body: box, flip_period: " + num(period) + "}\n")));
  CHECK_FALSE(early.passed());
  CHECK(early.quantity.find("2 are needed") != std::string::npos);
}

TEST_CASE("the symmetric top's precession in the body and in space, and its cone, against the closed forms") {
  // an oblate ellipsoid of semi-axes (0.3, 0.3, 0.1) at 100 kg/m³: I₁ = I₂ = m (a² + c²)/5 < I₃ = 2 m a²/5
  const std::string body = R"(
dimensions: 3
duration: 5
sim: {integrator: splitting, dt: 0.001}
bodies:
  - {name: top, shape: {ellipsoid: [0.3, 0.3, 0.1]}, density: 100, orientation: {axis: [1, -2, 0.5], angle: 0.7}}
)";
  SceneDef def = load(body);
  const Body b = buildBody(def.bodies[0]);
  const Vec3 omegaBody(1.0, 0.0, 5.0);
  def.bodies[0].angularVelocity = b.rotation() * omegaBody;
  const sim::world3d::SymmetricTop top{b.principalMoments[0], b.principalMoments[2], omegaBody};
  ExpectDef e;
  e.time = 5.0;
  e.body = "top";
  e.precessionRate = sim::world3d::bodyPrecessionRate(top);
  e.spacePrecessionRate = sim::world3d::spacePrecessionRate(top);
  e.coneAngle = sim::world3d::coneAngle(top);
  e.tolerance = 1e-4;
  def.expects = {e};
  const std::vector<CheckResult> results = runExpects(def);
  REQUIRE(results.size() == 3);
  for (const CheckResult& r : results) {
    MESSAGE(r.quantity, ": measured ", r.actual[0], ", closed form ", r.expected[0]);
    CHECK(r.passed());
  }
  // the splitting's O(h²): relative errors under (h|ω|)²
  CHECK(results[1].error < std::pow(0.001 * omegaBody.norm(), 2) * std::abs(*e.precessionRate));
  // oblate (I₃ > I₁): seen from the body, ω turns the way the body spins, Ω = ω₃ (I₃ − I₁)/I₁ > 0
  CHECK(results[1].actual[0] > 0.0);
}

TEST_CASE("explicit Euler without normalization: |q| grows by √(1 + (h|ω|/2)²) a step, to round-off") {
  const std::string scene = R"(
dimensions: 3
duration: 2
sim: {integrator: explicit_euler, dt: 0.01, normalize: false}
bodies:
  - {name: a, shape: {box: [1, 2, 3]}, angular_velocity: [0, 0, 4]}
)";
  const double growth = std::pow(1.0 + std::pow(0.01 * 4 / 2, 2), 200 / 2.0);
  const CheckResult r =
      only(runExpects(load(scene + "expect:\n  - {time: 2, body: a, quaternion_norm: " + num(growth) + ", tolerance: 1e-13}\n")));
  MESSAGE("|q| after 200 steps: ", r.actual[0], " (closed form ", growth, ")");
  CHECK(r.passed());
  CHECK(r.actual[0] > 1.01);
}

#include "render/analysis/sweep.h"

#include <doctest/doctest.h>

#include <cmath>

#include "sim/yaml/scene_yaml.h"

namespace {

// the spring bar of scenes/spring_bar.yaml, over 1 s: translation and rotation coupled
const char* kSpringBar = R"(
duration: 1
world: {gravity: [0, -9.81]}
bodies:
  - {name: bar, shape: {box: [0.1, 1.0]}, mass: 1, position: [0.3, -1.2], angle: 0.4}
forces:
  - {type: spring, body: bar, point: [0, 0.5], anchor: [0, 0], stiffness: 40, rest_length: 0.5}
)";

// least-squares slope of log(error) against log(dt)
double slope(const std::vector<render::analysis::SweepRow>& rows) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(rows.size());
  for (const render::analysis::SweepRow& r : rows) {
    const double x = std::log(r.method.dt), y = std::log(r.error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

TEST_CASE("the spring-bar sweep's work-precision slopes give each integrator's order: 1, 1, 2, 4 (±0.3)") {
  const sim::scene::SceneDef def = sim::yaml::loadSceneText(kSpringBar, "inline.yaml");
  struct Case {
    sim::core::Integrator method;
    double from, to;  // each method's asymptotic range, above the reference's and round-off's error
    double order;
  };
  const render::analysis::SweepReference reference = render::analysis::sweepReference(def, 2.5e-4);
  CHECK(reference.name.find("rk4") != std::string::npos);
  for (const Case& c : {Case{sim::core::Integrator::ExplicitEuler, 2e-3, 2.5e-4, 1},
                        Case{sim::core::Integrator::SymplecticEuler, 2e-3, 2.5e-4, 1},
                        Case{sim::core::Integrator::Midpoint, 8e-3, 1e-3, 2}, Case{sim::core::Integrator::Rk4, 4e-2, 5e-3, 4}}) {
    std::vector<render::analysis::SweepRow> rows;
    for (double h : render::analysis::parseRange(std::to_string(c.from) + ":" + std::to_string(c.to) + ":4", "--dt"))
      rows.push_back(render::analysis::runSweepCase(def, {c.method, sim::core::CollisionMethod::Auto, h, 0}, reference, 1));
    const double measured = slope(rows);
    MESSAGE(sim::core::integratorName(c.method), ": slope ", measured);
    CHECK(measured == doctest::Approx(c.order).epsilon(0.3 / c.order));
    for (const render::analysis::SweepRow& r : rows) {
      CHECK(r.finite);
      CHECK(r.steps == std::lround(1.0 / r.method.dt));
      CHECK(r.secondsPerSimSecond > 0.0);
      CHECK(r.maxPenetration == 0.0);  // one body: nothing to penetrate
    }
  }
}

TEST_CASE("a scene's expect answers are the sweep's reference when it has them") {
  const sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
duration: 1
world: {gravity: [0, -10]}
bodies: [{name: ball, shape: {circle: 0.1}, velocity: [1, 0]}]
expect: [{time: 1, body: ball, position: [1, -5], tolerance: 1e-9}]
)",
                                                            "inline.yaml");
  const render::analysis::SweepReference reference = render::analysis::sweepReference(def, 0.01);
  CHECK(reference.name == "expect");
  // symplectic Euler's height error is −g h t/2 = −0.05 at h = 0.01: exactly the sweep's error
  const render::analysis::SweepRow row = render::analysis::runSweepCase(
      def, {sim::core::Integrator::SymplecticEuler, sim::core::CollisionMethod::Auto, 0.01, 0}, reference, 1);
  CHECK(row.error == doctest::Approx(0.05).epsilon(1e-9));
  const render::analysis::SweepRow exact = render::analysis::runSweepCase(
      def, {sim::core::Integrator::Midpoint, sim::core::CollisionMethod::Auto, 0.01, 0}, reference, 1);
  CHECK(exact.error < 1e-12);
}

TEST_CASE("--dt ranges are log-spaced and checked") {
  const std::vector<double> v = render::analysis::parseRange("0.1:0.001:3", "--dt");
  REQUIRE(v.size() == 3);
  CHECK(v[0] == 0.1);
  CHECK(v[1] == doctest::Approx(0.01));
  CHECK(v[2] == doctest::Approx(0.001));
  CHECK_THROWS(render::analysis::parseRange("0.1:0:3", "--dt"));
  CHECK_THROWS(render::analysis::parseRange("0.1:0.01", "--dt"));
  CHECK_THROWS(render::analysis::parseRange("a:b:c", "--dt"));
}

TEST_CASE("a stack sweep: more iterations or substeps leave a 10-box column's top nearer its rest pose") {
  std::string yaml =
      "duration: 10\nworld: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
      "sim: {dt: 0.016666666666666667}\nbodies:\n"
      "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int i = 0; i < 10; ++i)
    yaml += "  - {name: box" + std::to_string(i) + ", shape: {box: [1, 1]}, position: [0, " + std::to_string(0.5 + i) + "]}\n";
  const sim::scene::SceneDef def = sim::yaml::loadSceneText(yaml, "inline.yaml");
  const render::analysis::SweepReference rest{render::analysis::kRestPose, {}};
  using sim::core::CollisionMethod;
  const auto run = [&](CollisionMethod c, int iterations, int substeps) {
    const render::analysis::SweepRow r =
        render::analysis::runSweepCase(def, {sim::core::Integrator::SymplecticEuler, c, def.dt, iterations, substeps}, rest, 1);
    MESSAGE(sim::core::collisionMethodName(c) << " " << iterations << " it, " << substeps << " substeps: top "
                                              << r.topDisplacement << " m, farthest " << r.maxDisplacement << " m");
    // the error of a stack sweep is its top body's displacement, the farthest body's at least that
    CHECK(r.error == r.topDisplacement);
    CHECK(r.maxDisplacement >= r.topDisplacement);
    return r.topDisplacement;
  };
  // two sequential iterations let the column sink 7.8 cm (it fell before the side slack of issue
  // 36 kept each box's contact points as the box turns by round-off); eight hold it within its slop
  const double two = run(CollisionMethod::Sequential, 2, 0), eight = run(CollisionMethod::Sequential, 8, 0);
  CHECK(eight < two);
  CHECK(eight < 0.05);
  CHECK(two > 0.05);
  // one soft substep lets it fall; four hold it
  const double one = run(CollisionMethod::SoftStep, 8, 1), four = run(CollisionMethod::SoftStep, 8, 4);
  CHECK(four < one);
  CHECK(four < 0.05);
}

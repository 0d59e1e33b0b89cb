#include "render/analysis/stability.h"

#include <doctest/doctest.h>

#include <cmath>

#include "sim/core/settings.h"
#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/yaml/scene_yaml.h"

namespace {

// the model and its stability: block, as `rigidreel stability` reads them
render::analysis::Study study(const std::string& yaml, const std::string& variant = "") {
  const sim::yaml::SceneSource source = sim::yaml::sceneSourceText(yaml, "inline.yaml", variant);
  render::analysis::Study s;
  s.model = sim::yaml::readModel(source, {{render::analysis::kStabilityKey}, {}});
  s.stability = render::analysis::readStability(source, s.model);
  return s;
}

// an undamped mass on a spring: m = 1, k = 4, so ω = 2
const char* kSpringMass = R"(
duration: 20
bodies: [{name: mass, shape: {circle: 0.1}, mass: 1, position: [1, 0]}]
forces: [{type: spring, body: mass, anchor: [0, 0], stiffness: 4}]
stability: {parameter: dt, from: 0.01}
)";
constexpr double kOmega = 2.0;

double boundary(const char* yaml, sim::core::Integrator method,
                sim::core::CollisionMethod collisions = sim::core::CollisionMethod::Auto, const std::string& variant = "") {
  render::analysis::Study def = study(yaml, variant);
  def.model.integrator = method;
  if (collisions != sim::core::CollisionMethod::Auto) def.model.collisions = collisions;
  const render::analysis::StabilityResult r = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, r));
  CHECK_FALSE(r.failsEverywhere);
  CHECK_FALSE(r.holdsToLimit);
  return r.largestStable;
}

}  // namespace

TEST_CASE("mass on a spring: symplectic Euler holds up to h·ω = 2, RK4 up to h·ω = 2√2 (within 5 %)") {
  CHECK(boundary(kSpringMass, sim::core::Integrator::SymplecticEuler) * kOmega == doctest::Approx(2.0).epsilon(0.05));
  CHECK(boundary(kSpringMass, sim::core::Integrator::Rk4) * kOmega == doctest::Approx(2.0 * std::sqrt(2.0)).epsilon(0.05));
}

TEST_CASE("mass on a spring: explicit Euler gains the factor 1 + (hω)² a step; the search stops near a tenth") {
  // explicit Euler on a linear spring is a linear map whose energy factor per step is exactly
  // q = 1 + (hω)²: there is no stable step, only one small enough that the run gains little
  const double h = boundary(kSpringMass, sim::core::Integrator::ExplicitEuler);
  const double steps = std::floor(std::max(20.0, render::analysis::kMinimumSteps * h) / h);
  const double q = 1.0 + (h * kOmega) * (h * kOmega);
  const double gain = std::pow(q, steps) - 1.0;
  // the run the search judged holding gains about the 10 % its criterion allows (more than 5 %,
  // less than 25 %: the criterion compares thirds of the run, not its ends)
  CHECK(gain > 0.05);
  CHECK(gain < 0.25);
  // and the simulation at that step gains exactly q^N: E(N h) = E(0) q^N to round-off
  render::analysis::Study s = study(kSpringMass);
  s.model.integrator = sim::core::Integrator::ExplicitEuler;
  s.model.dt = h;
  sim::world::World w = sim::scene::buildWorld(s.model);
  const double e0 = sim::world::energy(w).total();
  w.advanceTo(steps * h);
  CHECK(w.steps == static_cast<long>(steps));
  CHECK(sim::world::energy(w).total() / e0 == doctest::Approx(std::pow(q, steps)).epsilon(1e-9));
}

TEST_CASE("tunneling: the stepped methods' speed limit follows from the thicknesses; event never tunnels") {
  // a 5 cm body toward a 5 cm wall, dt = 1/60. `isolated` pushes an overlapping pair apart along
  // the normal of least overlap, so a body that a step carries more than halfway through the two
  // thicknesses (0.05 m) is pushed out on the far side: it tunnels from (0.05 + 0.05)/2 / dt = 3 m/s
  const char* yaml = R"(
duration: 0.5
world: {restitution: 1}
sim: {dt: 0.016666666666666667}
bodies:
  - {name: wall, shape: {box: [0.05, 2.0]}, static: true}
  - {name: bullet, shape: {box: [0.05, 0.2]}, mass: 0.1, position: [-1, 0], velocity: [1, 0]}
stability: {parameter: speed, body: bullet, from: 0.5, to: 10000}
)";
  const double allowed = 0.5 * (0.05 + 0.05) * 60.0;
  CHECK(boundary(yaml, sim::core::Integrator::SymplecticEuler, sim::core::CollisionMethod::Isolated) ==
        doctest::Approx(allowed).epsilon(0.10));

  render::analysis::Study def = study(yaml);
  def.model.collisions = sim::core::CollisionMethod::Event;
  const render::analysis::StabilityResult r = render::analysis::findBoundary(def);
  CHECK(r.holdsToLimit);
}

TEST_CASE("the stack criterion: isolated lets a stack drift or sink, sequential holds it") {
  std::string yaml = R"(
duration: 3
world: {gravity: [0, -10], friction: 0.6, restitution: 0}
sim: {dt: 0.016666666666666667}
stability: {parameter: stack_height, to: 6}
bodies:
  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
)";
  for (int i = 0; i < 6; ++i)
    yaml += "  - {name: box" + std::to_string(i) + ", shape: {box: [1, 1]}, position: [0, " + std::to_string(0.5 + i) + "]}\n";
  render::analysis::Study def = study(yaml);
  def.model.collisions = sim::core::CollisionMethod::Sequential;
  const render::analysis::StabilityResult held = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, held));
  CHECK(held.holdsToLimit);
  CHECK(held.largestStable == 6.0);
  def.model.collisions = sim::core::CollisionMethod::Isolated;
  const render::analysis::StabilityResult isolated = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, isolated));
  CHECK(isolated.largestStable < 6.0);
}

TEST_CASE("a search stops at the scene's max_steps, over all its runs, and says so") {
  // explicit Euler gains energy on a spring at every dt; each halving doubles a run's steps
  std::string yaml = kSpringMass;
  yaml += "sim: {max_steps: 20000}\n";
  render::analysis::Study def = study(yaml);
  def.model.integrator = sim::core::Integrator::ExplicitEuler;
  const render::analysis::StabilityResult r = render::analysis::findBoundary(def);
  const std::string said = render::analysis::describeFailure(def, r);
  MESSAGE(said);
  CHECK(r.budgetSpent);
  CHECK(r.failsEverywhere);
  // runs of 2000 (dt 0.01), 4000 and 8000 steps fit; the next, 16000, would pass 20000
  CHECK(r.steps == 14000.0);
  CHECK(r.firstFailing == doctest::Approx(0.0025));
  CHECK(said.find("stopped early, after 14000 steps") != std::string::npos);
  CHECK(said.find("max_steps") != std::string::npos);
}

namespace {

// a column of `height` 1 m boxes on the ground, Box2D's benchmark settings, and a stability block
std::string boxColumn(int height, const std::string& stability) {
  std::string yaml =
      "duration: 10\nworld: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
      "sim: {dt: 0.016666666666666667}\nstability: " +
      stability +
      "\nbodies:\n"
      "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int i = 0; i < height; ++i)
    yaml += "  - {name: box" + std::to_string(i) + ", shape: {box: [1, 1]}, position: [0, " + std::to_string(0.5 + i) + "]}\n";
  return yaml;
}

}  // namespace

TEST_CASE("the fewest search brackets the boundary: the value it names holds, the one below fails") {
  // a scene that holds from 7 on: doubling finds 8, bisection comes down to 7 and 6
  int runs = 0;
  const render::analysis::StabilityResult r =
      render::analysis::searchFewest(1.0, 64.0, [&](double n, render::analysis::RunMetrics&) {
        ++runs;
        return n >= 7.0;
      });
  CHECK(r.fewest);
  CHECK(r.largestStable == 7.0);
  CHECK(r.firstFailing == 6.0);
  CHECK_FALSE(r.holdsToLimit);
  CHECK_FALSE(r.failsEverywhere);
  CHECK(runs == 6);  // 1, 2, 4, 8, then 6 and 7
  // never holding up to the limit, or holding from the first value, is said as such
  CHECK(render::analysis::searchFewest(1.0, 16.0, [](double, render::analysis::RunMetrics&) { return false; }).failsEverywhere);
  CHECK(render::analysis::searchFewest(1.0, 16.0, [](double, render::analysis::RunMetrics&) { return true; }).holdsToLimit);
}

TEST_CASE("iterations: the fewest sequential iterations that hold a 10-box column within 5 cm, at rest") {
  render::analysis::Study def = study(boxColumn(10, "{parameter: iterations, within: 0.05, to: 64}"));
  def.model.collisions = sim::core::CollisionMethod::Sequential;
  const render::analysis::StabilityResult r = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, r));
  REQUIRE_FALSE(r.failsEverywhere);
  REQUIRE_FALSE(r.holdsToLimit);
  // the two values that bracket the boundary: the one named holds, the one below does not
  CHECK(r.firstFailing == r.largestStable - 1.0);
  render::analysis::RunMetrics m;
  CHECK(render::analysis::holdsAt(def, r.largestStable, m));
  CHECK(m.maxDisplacement <= 0.05);
  CHECK(m.fastest <= render::analysis::kRestSpeed);
  CHECK_FALSE(render::analysis::holdsAt(def, r.firstFailing, m));
  CHECK(std::string(m.failure) == "a body leaves its rest pose");
  // a single iteration cannot pass the load of ten boxes down in a step
  CHECK(r.largestStable > 1.0);
}

TEST_CASE("substeps: soft_step needs more than one substep for a 10-box column, and says where") {
  render::analysis::Study def = study(boxColumn(10, "{parameter: substeps, within: 0.05, to: 16}"));
  def.model.collisions = sim::core::CollisionMethod::SoftStep;
  const render::analysis::StabilityResult r = render::analysis::findBoundary(def);
  const std::string said = render::analysis::describeFailure(def, r);
  MESSAGE(said);
  REQUIRE_FALSE(r.failsEverywhere);
  CHECK(r.largestStable > 1.0);
  CHECK(r.firstFailing == r.largestStable - 1.0);
  CHECK(said.find("; holds from " + std::to_string(static_cast<int>(r.largestStable))) != std::string::npos);
}

TEST_CASE("pyramid_base grows the listed pyramid: sequential holds Box2D's pyramid to the limit, isolated does not") {
  // base 3, touching rows, Box2D's benchmark settings; the search grows it by doubling up to 12
  std::string yaml = R"(
duration: 3
world: {gravity: [0, -10], friction: 0.6, restitution: 0}
sim: {dt: 0.016666666666666667, iterations: 8, position_iterations: 3}
stability: {parameter: pyramid_base, to: 12}
bodies:
  - {name: ground, shape: {box: [80, 1]}, static: true, position: [0, -0.5]}
)";
  for (int row = 0; row < 3; ++row)
    for (int k = 0; k < 3 - row; ++k)
      yaml += "  - {name: p" + std::to_string(row) + std::to_string(k) + ", shape: {box: [1, 1]}, position: [" +
              std::to_string(1.125 * k + 0.5625 * row) + ", " + std::to_string(0.5 + row) + "]}\n";
  render::analysis::Study def = study(yaml);
  CHECK(def.stability.stack);
  def.model.collisions = sim::core::CollisionMethod::Sequential;
  const render::analysis::StabilityResult held = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, held));
  CHECK(held.holdsToLimit);
  CHECK(held.largestStable == 12.0);
  // a base-12 pyramid is 78 boxes, the largest run of the search
  CHECK(render::analysis::withParameter(def, 12.0).model.bodies.size() == 1 + 78);
  def.model.collisions = sim::core::CollisionMethod::Isolated;
  const render::analysis::StabilityResult isolated = render::analysis::findBoundary(def);
  MESSAGE(render::analysis::describeFailure(def, isolated));
  CHECK(isolated.largestStable < 3.0);
}

TEST_CASE("pyramid_base on bodies that are not a pyramid is refused at the stability block's line") {
  const std::string yaml = R"(bodies:
  - {name: a, shape: {box: [1, 1]}}
  - {name: b, shape: {box: [1, 1]}, position: [0, 1]}
stability: {parameter: pyramid_base}
)";
  try {
    study(yaml);
    FAIL("expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    const std::string what = e.what();
    MESSAGE(what);
    CHECK(what.find("inline.yaml:4:") != std::string::npos);
    CHECK(what.find("pyramid_base") != std::string::npos);
    CHECK(what.find("choose stack_height") != std::string::npos);
  }
}

TEST_CASE("pyramid_base keeps to the scene's bodies limit before any run, and starts below its 'to'") {
  std::string pyramid = "bodies:\n  - {name: ground, shape: {box: [80, 1]}, static: true, position: [0, -0.5]}\n";
  for (int row = 0; row < 3; ++row)
    for (int k = 0; k < 3 - row; ++k)
      pyramid += "  - {name: p" + std::to_string(row) + std::to_string(k) + ", shape: {box: [1, 1]}, position: [" +
                 std::to_string(1.125 * k + 0.5625 * row) + ", " + std::to_string(0.5 + row) + "]}\n";
  const auto refused = [&](const std::string& block, const std::string& said) {
    try {
      study(pyramid + block);
      FAIL("expected a SceneError for: " << block);
    } catch (const sim::yaml::SceneError& e) {
      MESSAGE(std::string(e.what()));
      CHECK(std::string(e.what()).find(said) != std::string::npos);
    }
  };
  // the ground and a pyramid of base 5 are 16 bodies: a limit of 15 takes base 4 at most
  refused("sim: {max_bodies: 15}\nstability: {parameter: pyramid_base, to: 5}\n", "the largest base within it: 4");
  refused("stability: {parameter: pyramid_base, to: 447}\n", "more bodies than the limit of 100000");
  refused("stability: {parameter: pyramid_base, to: 3}\n", "starts at the listed pyramid's base, 3");
  refused("stability: {parameter: pyramid_base, from: 446}\n", "'from' must be below 'to', 446");
  // the boxes are rebuilt under other names: nothing may name them (nor a stack's dropped boxes)
  refused("events: [{time: 1, body: p20, impulse: [1, 0]}]\nstability: {parameter: pyramid_base, to: 6}\n",
          "pyramid_base drops or rebuilds the dynamic bodies, but an event names 'p20'");
  refused("forces: [{type: spring, body: p00, anchor: [0, 5], stiffness: 1}]\nstability: {parameter: stack_height, to: 6}\n",
          "stack_height drops or rebuilds the dynamic bodies, but a spring names 'p00'");
  // without 'to': the largest base the limit allows
  CHECK(study(pyramid + "sim: {max_bodies: 15}\nstability: {parameter: pyramid_base}\n").stability.to == 4.0);
  CHECK(study(pyramid + "sim: {max_bodies: 16}\nstability: {parameter: pyramid_base}\n").stability.to == 5.0);
  CHECK(study(pyramid + "stability: {parameter: pyramid_base}\n").stability.to == 446.0);
}

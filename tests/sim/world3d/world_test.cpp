#include "sim/world3d/world.h"

#include <doctest/doctest.h>

#include "sim/world3d/diagnostics.h"
#include "support/world3d_fixtures.h"
#include "support/redefined.h"

using namespace sim::world3d;

namespace {

constexpr Integrator kAll[] = {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::Midpoint, Integrator::Rk4,
                               Integrator::Splitting};

class Recorder : public StepObserver {
 public:
  std::vector<double> stepTimes, eventTimes;
  void afterStep(const World& w) override { stepTimes.push_back(w.time); }
  void afterEvent(const World& w, const ImpulseEvent&) override { eventTimes.push_back(w.time); }
};

bool sameState(const World& a, const World& b) {
  for (size_t i = 0; i < a.bodies.size(); ++i) {
    const Body &p = a.bodies[i], &q = b.bodies[i];
    if (p.x != q.x || p.q.coeffs() != q.q.coeffs() || p.v != q.v || p.omega != q.omega) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("the step grid is split exactly at events and force switches, and events at 0 and at the end apply") {
  World w = fixtures3d::freeBox(Integrator::Rk4, 0.1);
  w = fixtures::redefined(w, [&](auto& d) {
    d.events = {{0.25, 0, Vec3::Zero(), false, Vec3(1, 0, 0)},
                {0.0, 0, Vec3::Zero(), false, Vec3(0, 1, 0)},
                {0.5, 0, Vec3::Zero(), false, Vec3(0, 0, 1)}};
    d.forces.pointForces.push_back({0, Vec3::Zero(), Vec3(0, 0, 1), false, 0.33, 0.45});
  });
  Recorder r;
  w.advanceTo(0.5, &r);
  CHECK(r.stepTimes == std::vector<double>{0.1, 0.2, 0.25, 3 * 0.1, 0.33, 4 * 0.1, 0.45, 0.5});
  CHECK(r.eventTimes == std::vector<double>{0.0, 0.25, 0.5});
  CHECK(w.time == 0.5);
  CHECK(w.steps == 8);
}

TEST_CASE("a timed force changes the momentum by f × its duration, exactly, with every integrator") {
  for (Integrator m : kAll) {
    CAPTURE(kIntegratorNames.name(m));
    World w = fixtures3d::freeBox(m, 0.01);
    w = fixtures::redefined(w, [&](auto& d) {
      d.forces.pointForces.push_back({0, Vec3(0.1, 0, 0), Vec3(0, 2.0, 0), false, 0.033, 0.5});
    });
    const Vec3 p0 = linearMomentum(w);
    w.advanceTo(1.0);
    CHECK((linearMomentum(w) - p0 - Vec3(0, 2.0 * 0.467, 0)).norm() < 1e-14);
  }
}

TEST_CASE("advancing in pieces that end on grid points gives the bit-identical run; other ends split a step") {
  const double dt = 1.0 / 64;  // grid points exact in binary
  for (Integrator m : kAll) {
    CAPTURE(kIntegratorNames.name(m));
    World once = fixtures3d::springChain(m, dt), pieces = fixtures3d::springChain(m, dt);
    once.advanceTo(1.0);
    for (double t : {0.25, 0.5, 0.5, 0.75, 1.0}) pieces.advanceTo(t);
    CHECK(pieces.steps == once.steps);
    CHECK(sameState(once, pieces));
    // a stop between grid points splits that step in two, and the grid goes on where it was
    World split = fixtures3d::springChain(m, dt);
    split.advanceTo(0.3);
    Recorder r;
    split.advanceTo(1.0, &r);
    CHECK(split.steps == once.steps + 1);
    CHECK(r.stepTimes.front() == 20 * dt);
  }
}

TEST_CASE("advanceWithin takes the run's own steps up to a time between them, never splitting one") {
  for (Integrator m : kAll) {
    CAPTURE(kIntegratorNames.name(m));
    World once = fixtures3d::springChain(m, 0.01), within = fixtures3d::springChain(m, 0.01);
    const auto withEvent = [](auto& d) { d.events = {{0.333, 0, Vec3::Zero(), false, Vec3(0, 1, 0)}}; };
    once = fixtures::redefined(once, withEvent);
    within = fixtures::redefined(within, withEvent);
    Recorder a, b;
    once.advanceTo(0.755, &a);
    // pictures at 1/60 s, the end of the run 0.755 s
    for (int k = 0; k < 46; ++k) within.advanceWithin(k / 60.0, 0.755, &b);
    CHECK(within.time == doctest::Approx(0.75).epsilon(1e-12));
    within.advanceTo(0.755, &b);
    CHECK(b.stepTimes == a.stepTimes);
    CHECK(b.eventTimes == a.eventTimes);
    CHECK(sameState(once, within));
  }
}

TEST_CASE("a state that stops being finite is an error naming the time and the body") {
  // a stiff spring on the second body under explicit Euler: h ω = 10, |state| grows tenfold a step
  World w = fixtures3d::springChain(Integrator::ExplicitEuler, 0.01);
  w = fixtures::redefined(w, [&](auto& d) {
    d.forces.springs.push_back({1, Vec3::Zero(), sim::core::kWorldAnchor, Vec3::Zero(), 1e6 * w.bodies[1].mass, 0.0, 0.0});
  });
  try {
    w.advanceTo(100.0);
    FAIL("no divergence");
  } catch (const sim::core::Diverged& e) {
    MESSAGE(std::string(e.what()));
    CHECK(e.time == w.time);
    CHECK(e.time < 10.0);
    CHECK(std::string(e.what()).find("t = ") != std::string::npos);
    CHECK(!isFinite(w.bodies[e.body].x) + !isFinite(w.bodies[e.body].v) + !isFinite(w.bodies[e.body].q) +
              !isFinite(w.bodies[e.body].omega) >
          0);
    CHECK(std::string(e.what()).find("body " + std::to_string(e.body)) != std::string::npos);
  }
}

TEST_CASE("a step that is not positive is refused when the run starts") {
  World w = fixtures3d::freeBox(Integrator::Rk4, 0.0);
  CHECK_THROWS_AS(w.advanceTo(1.0), std::invalid_argument);
}

TEST_CASE("the grid finds every pair of spheres within the margin that testing every pair finds, in the same order") {
  World w;
  // 300 spheres of three sizes in a 2 m cube: crowded enough that many touch, some far apart
  unsigned seed = 12345;
  const auto uniform = [&seed] { return (seed = seed * 1103515245u + 12345u) % 100000 / 100000.0; };
  for (int i = 0; i < 300; ++i) {
    Body b = makeBody(makeSphere(0.05 + 0.05 * (i % 3)), 1.0);
    b.x = Vec3(2 * uniform(), 2 * uniform(), 2 * uniform());
    w.bodies.push_back(b);
  }
  // the grid, then every pair again once a sphere far away is past the reach of its keys
  Body far = makeBody(makeSphere(0.1), 1.0);
  far.x = Vec3(1e9, 0, 0);
  for (const double margin : {0.0, 0.02, 0.01}) {
    if (margin == 0.01) w.bodies.push_back(far);
    std::vector<std::pair<int, int>> expected;
    for (size_t i = 0; i < w.bodies.size(); ++i)
      for (size_t j = i + 1; j < w.bodies.size(); ++j)
        if ((w.bodies[i].x - w.bodies[j].x).norm() - w.bodies[i].shape.radius - w.bodies[j].shape.radius <= margin)
          expected.emplace_back(static_cast<int>(i), static_cast<int>(j));
    std::vector<std::pair<int, int>> found;
    for (const Contact3& c : w.findContacts(margin)) found.emplace_back(c.a, c.b);
    CAPTURE(margin);
    REQUIRE(expected.size() > 100);
    CHECK(found == expected);
  }
}

// The `sequential` method (sequential_solver.cpp): sequential impulses with warm starting,
// friction and position correction (Box2D 2.4): stacks stand, fast thin bodies tunnel.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"
#include "support/scene_text.h"

namespace {

using namespace scene_text;

const char* kSolverSettings =
    "world: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
    "sim: {collisions: sequential, dt: 0.016666666666666667, iterations: 8, position_iterations: 3}\n"
    "bodies:\n";

// box_stack.yaml: ten 1 m boxes on a plane
std::string boxStack() {
  std::string s = std::string(kSolverSettings) + "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int i = 0; i < 10; ++i)
    s += "  - {name: box" + std::to_string(i + 1) + ", shape: {box: [1, 1]}, position: " + vec(0, 0.5 + i) + "}\n";
  return s;
}

// pyramid.yaml: a ground box 80 × 1 centered at (0, −0.5); rows r = 0 … 19 of 20 − r boxes resting
// on each other, box j of row r at (−7 + 0.5625 r + 1.125 j, 0.5 + r); 210 boxes. Dropped: Box2D's
// testbed layout, each row starting 0.25 m above the one below (y = 0.75 + 1.25 r); under gravity g
std::string pyramid(bool dropped = false, int positionIterations = 3, double g = 10.0) {
  std::string s = std::string(kSolverSettings) + "  - {name: ground, shape: {box: [80, 1]}, static: true, position: [0, -0.5]}\n";
  s.replace(s.find("position_iterations: 3"), 22, "position_iterations: " + std::to_string(positionIterations));
  s.replace(s.find("gravity: [0, -10]"), 17, "gravity: " + vec(0, -g));
  for (int r = 0; r < 20; ++r)
    for (int j = 0; j < 20 - r; ++j)
      s += "  - {name: b" + std::to_string(r + 1) + "_" + std::to_string(j + 1) +
           ", shape: {box: [1, 1]}, position: " + vec(-7.0 + 0.5625 * r + 1.125 * j, dropped ? 0.75 + 1.25 * r : 0.5 + r) + "}\n";
  return s;
}

// the most negative separation of any contact point now (0 when nothing overlaps)
double deepest(const sim::world::World& w) {
  double d = 0.0;
  for (const sim::world::Contact& c : w.findContacts(sim::core::settings::kContactMargin))
    for (int k = 0; k < c.manifold.count; ++k) d = std::min(d, c.manifold.points[k].separation);
  return d;
}

// the standing criterion, sampled at every step: how far the top box strays, the deepest
// penetration, and whether any state stopped being finite
class StandWatch : public sim::world::StepObserver {
 public:
  StandWatch(const sim::world::World& w, int top) : top(top), start(w.bodies[top].x) {}
  void afterStep(const sim::world::World& w) override {
    const double d = (w.bodies[top].x - start).norm();
    if (d > moved) moved = d, movedAt = w.time;
    penetration = std::max(penetration, -deepest(w));
    for (const sim::core::Body& b : w.bodies)
      finite = finite && sim::core::isFinite(b.x) && std::isfinite(b.angle) && sim::core::isFinite(b.v) && std::isfinite(b.omega);
    ++steps;
  }
  int top;
  sim::core::Vec2 start;
  double moved = 0.0, movedAt = 0.0, penetration = 0.0;
  bool finite = true;
  int steps = 0;
};

void checkStands(const std::string& yaml, const char* name, size_t bodies) {
  sim::world::World w = build(yaml);
  REQUIRE(w.bodies.size() == bodies);
  REQUIRE(w.collisions() == sim::core::CollisionMethod::Sequential);
  const int top = static_cast<int>(w.bodies.size()) - 1;
  StandWatch watch(w, top);
  const auto t0 = std::chrono::steady_clock::now();
  w.advanceTo(10.0, &watch);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MESSAGE(std::string(name) << ", sequential, 10 s (" << watch.steps << " steps, " << seconds
                            << " s wall): top box strayed up to " << watch.moved << " m (at t = " << watch.movedAt << " s), ends "
                            << (w.bodies[top].x - watch.start).norm() << " m from its start, at (" << num(w.bodies[top].x.x())
                            << ", " << num(w.bodies[top].x.y()) << "); deepest penetration " << watch.penetration << " m");
  CHECK(watch.steps == 600);
  CHECK(watch.finite);
  const double box = 1.0;
  // where the top box is after the 10 s (the scene's own `expect`): less than 5 % of a box from its
  // start; on the way it may dip while the solver takes up the load (see the pyramid below), but
  // never by more than 10 %
  CHECK((w.bodies[top].x - watch.start).norm() < 0.05 * box);
  CHECK(watch.moved < 0.10 * box);
  CHECK(watch.penetration < 2.0 * sim::core::settings::kLinearSlop);
  // and still at the end
  CHECK(w.bodies[top].v.norm() < 0.01);
  CHECK(std::abs(w.bodies[top].omega) < 0.01);
}

}  // namespace

TEST_CASE("sequential: the 10-box stack stands for 10 s") { checkStands(boxStack(), "box stack", 11); }

// mass_ratio_stack.yaml at 50 : 1, a box of 50 kg on three of 1 kg: it holds because each box turned
// by round-off on the one under it keeps its contact points and their warm start (the side slack,
// settings::kClipSideSlack); with the clipping at the edges' ends it fell at 27 : 1 (`rigidreel
// stability scenes/mass_ratio_stack.yaml`: 5.36 times the scene's 5 : 1, now 18.6). Box2D 2.4 holds
// such a column to 60 : 1 (rigidreel_stack_bench, a ground box). The light boxes give 3 cm under
// the load at first, so the criterion is the scene's: every box within 5 cm and at rest at the end
TEST_CASE("sequential: a box 50 times heavier than each of the three under it stands for 10 s") {
  std::string s = std::string(kSolverSettings) + "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int i = 0; i < 4; ++i)
    s += "  - {name: box" + std::to_string(i + 1) + ", shape: {box: [1, 1]}, density: " + (i == 3 ? "50" : "1") +
         ", position: " + vec(0, 0.5 + i) + "}\n";
  sim::world::World w = build(s);
  w.advanceTo(10.0);
  for (int i = 1; i <= 4; ++i) {
    CAPTURE(i);
    MESSAGE("box " << i << " ends " << (w.bodies[i].x - sim::core::Vec2(0, i - 0.5)).norm() << " m from its start, at "
                   << w.bodies[i].v.norm() << " m/s");
    CHECK((w.bodies[i].x - sim::core::Vec2(0, i - 0.5)).norm() < 0.05);
    CHECK(w.bodies[i].v.norm() < 0.01);
    CHECK(std::abs(w.bodies[i].omega) < 0.01);
  }
}

// Measured: the top box dips 0.0552 m in the first 0.15 s (the rows start exactly touching, and
// 8 Gauss–Seidel sweeps per step cannot pass the load of 20 rows down at once, so the upper rows
// fall a little until the accumulated, warm-started impulses hold them), rebounds, and settles
// 0.0356 m from its start (0.0343 m lower, as each of the 20 contact layers sinks into its slop).
// The criterion is therefore the position after the 10 s (5 %), with the transient dip bounded
// by 10 %.
TEST_CASE("sequential: the 20-base pyramid (210 boxes) stands for 10 s") { checkStands(pyramid(), "pyramid", 211); }

namespace {

// how the dropped pyramid ends after 10 s: the largest |x − rest x| (rest x is where each box
// starts) and the fastest body
struct Settled {
  double offRestX = 0.0, fastest = 0.0;
};

Settled dropPyramid(int positionIterations, double g) {
  sim::world::World w = build(pyramid(true, positionIterations, g));
  std::vector<double> restX;
  for (const sim::core::Body& b : w.bodies) restX.push_back(b.x.x());
  w.advanceTo(10.0);
  Settled s;
  for (size_t i = 1; i < w.bodies.size(); ++i) {
    s.offRestX = std::max(s.offRestX, std::abs(w.bodies[i].x.x() - restX[i]));
    s.fastest = std::max(s.fastest, w.bodies[i].v.norm() + 0.5 * std::abs(w.bodies[i].omega));
  }
  return s;
}

// the median of five values
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

// Box2D's testbed pyramid drops into place. Where each box lands is chaotic: a thousandth more or
// less gravity moves the bulge by centimetres (`rigidreel_stack_bench --layout pyramid:20:dropped
// --gravity -G --position-iterations P`, G = 9.98 … 10.02: 3 passes 0.033, 0.058, 0.058, 0.057,
// 0.057 m; 10 passes 0.088, 0.091, 0.072, 0.063, 0.060 m), so it is judged on the median of five
// runs at gravity nudged by 0.1 % steps. More passes bulge it more since the polygon pairs clip
// with Box2D's side slack (before, 0.058 and 0.060 m at the median), as they do in Box2D
// 2.4 itself (the same bench: 0.068 and 0.098 m). Before the flip-invariant feature ids it bulged
// 0.36 m and crept at 0.02 m/s.
TEST_CASE("sequential: the dropped 20-base pyramid settles in place, with 3 position passes and with 10") {
  std::vector<double> three, ten;
  for (double g : {9.98, 9.99, 10.0, 10.01, 10.02})
    for (int passes : {3, 10}) {
      CAPTURE(g);
      CAPTURE(passes);
      const Settled s = dropPyramid(passes, g);
      MESSAGE("dropped pyramid, g = " << g << ", " << passes << " position passes: max |x - rest x| " << s.offRestX
                                      << " m, fastest point speed " << s.fastest << " m/s");
      // at rest (every box's corners slower than 1 cm/s), and no box more than 0.2 m off
      CHECK(s.fastest < 0.01);
      CHECK(s.offRestX < 0.2);
      (passes == 3 ? three : ten).push_back(s.offRestX);
    }
  // every box within 0.1 m of its rest x
  CHECK(median(three) < 0.1);
  CHECK(median(ten) < 0.1);
}

TEST_CASE("sequential: warm starting carries the accumulated impulses from step to step") {
  // one 1 m box (density 1: m = 1 kg) resting on a plane, g = 10, dt = 1/60: the floor must give
  // it the impulse m g dt in every step, shared by the two corners
  sim::world::World w = build(std::string(kSolverSettings) +
                              "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
                              "  - {name: box, shape: {box: [1, 1]}, position: [0, 0.5]}\n");
  const double m = w.bodies[1].mass, g = 10.0, dt = w.def().dt;
  REQUIRE(m == doctest::Approx(1.0).epsilon(1e-15));
  const double support = m * g * dt;
  for (int n = 1; n <= 5; ++n) {
    w.advanceTo(n * dt);
    REQUIRE(w.contacts.size() == 1);
    const sim::world::Contact& c = w.contacts[0];
    REQUIRE(c.manifold.count == 2);
    CAPTURE(n);
    CHECK(c.state[0].normalImpulse + c.state[1].normalImpulse == doctest::Approx(support).epsilon(1e-6));
    // a symmetric box: each corner carries half
    CHECK(c.state[0].normalImpulse == doctest::Approx(support / 2).epsilon(1e-6));
    CHECK(w.bodies[1].v.norm() <= 1e-6 * g * dt);
  }
  // now no velocity iterations at all: the same bodies and contacts go on in a world without them
  // (a world's definition is fixed), where what holds the box in the next step is only the impulse
  // carried over from the last one and applied again by the warm start. It must be the whole
  // support (the box stays at rest), and it is carried on unchanged.
  sim::world::WorldDef noIterations = w.def();
  noIterations.velocityIterations = 0;
  sim::world::World held(noIterations, w.bodies);
  held.contacts = w.contacts;
  const sim::core::Vec2 before = held.bodies[1].x;
  held.advanceTo(dt);
  REQUIRE(held.contacts.size() == 1);
  const sim::world::Contact& c = held.contacts[0];
  CHECK(c.state[0].normalImpulse + c.state[1].normalImpulse == doctest::Approx(support).epsilon(1e-6));
  CHECK(held.bodies[1].v.norm() <= 1e-6 * g * dt);
  CHECK((held.bodies[1].x - before).norm() <= 1e-6 * g * dt * dt);
}

namespace {

// the thin body and thin wall of tunneling.yaml, the body starting at x0 (off the lattice of the
// step grid, so that no step starts with the body exactly on the wall's center line)
constexpr double kX0 = -1.0123, kDt = 1.0 / 60.0;

std::string tunneling(double speed) {
  return std::string(
             "world: {restitution: 1}\nsim: {collisions: sequential, dt: 0.016666666666666667}\n"
             "bodies:\n"
             "  - {name: wall, shape: {box: [0.05, 2.0]}, static: true}\n"
             "  - {name: bullet, shape: {box: [0.05, 0.2]}, mass: 0.1, position: ") +
         vec(kX0, 0) + ", velocity: " + vec(speed, 0) + "}\n";
}

bool passesThrough(double speed) {
  sim::world::World w = build(tunneling(speed));
  w.advanceTo(std::max(5.0 * kDt, 3.0 / speed));
  return w.bodies[1].x.x() > 0.05;
}

// the geometry: sequential finds contacts where the step starts (x0 + k v dt, k ≥ 0), within the
// contact margin: a gap up to the margin is closed but not overrun, and an overlap with the body's
// center short of the wall's is pushed back; from past the center line the least-penetration
// normal points forward. So the body is stopped when a step starts with −0.05 − margin ≤ x < 0.
bool sequentialCatches(double speed) {
  const double margin = sim::core::settings::kContactMargin;
  for (int k = 0; kX0 + (k - 1) * speed * kDt < 0.1; ++k) {
    const double x = kX0 + k * speed * kDt;
    if (x >= -0.05 - margin && x < 0.0) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("sequential: the lowest tunneling speed, against the geometry; fast bodies pass through") {
  const double thickness = 0.1, margin = sim::core::settings::kContactMargin;
  double lowest = 0.0;
  for (double speed = 1.0; speed <= 1e5; speed *= 2.0) {
    CAPTURE(speed);
    const bool through = passesThrough(speed);
    CHECK(through == !sequentialCatches(speed));
    // it cannot skip the 0.05 m + margin window in front of the wall's center line unless it moves
    // farther than that in one step
    if (speed * kDt < 0.05 + margin) CHECK_FALSE(through);
    if (through && lowest == 0.0) lowest = speed;
  }
  REQUIRE(lowest > 0.0);
  MESSAGE("sequential: lowest tunneling speed by doubling from 1 m/s: " << lowest << " m/s (" << lowest * kDt << " m per step)");
  CHECK(lowest * kDt > 0.05 + margin);
  CHECK(lowest <= 2.0 * (thickness + 2.0 * margin) / kDt);

  // the known failure: a fast thin body passes straight through (tunneling.yaml's 200 m/s, and
  // faster), as the step-start positions predict
  for (double speed : {200.0, 1e3, 1e4, 1e5}) {
    CAPTURE(speed);
    CHECK_FALSE(sequentialCatches(speed));
    CHECK(passesThrough(speed));
  }

  double first = 0.0;
  for (double speed = 0.25; speed <= 16.0; speed += 0.25) {
    CAPTURE(speed);
    const bool through = passesThrough(speed);
    CHECK(through == !sequentialCatches(speed));
    if (through && first == 0.0) first = speed;
  }
  MESSAGE("sequential: lowest tunneling speed on a 0.25 m/s scan: " << first << " m/s (" << first * kDt << " m per step)");
  CHECK(first * kDt > 0.05 + margin);
  CHECK(first <= (thickness + 2.0 * margin) / kDt);
}

TEST_CASE("Newton's cradle under sequential: momentum kept, the energy bounded") {
  const scene_text::CradleRun r = scene_text::runCradle(sim::core::CollisionMethod::Sequential);
  const sim::world::World& w = r.world;
  const sim::core::Vec2 p0 = r.p0;
  const double e0 = r.e0, e1 = r.e1;
  MESSAGE("cradle, sequential: kinetic energy " << num(e0) << " J -> " << num(e1) << " J; ball speeds" << r.speeds);
  CHECK((sim::world::linearMomentum(w) - p0).norm() <= 1e-9);
  CHECK(e1 > 0.0);
  CHECK(e1 <= e0 + 1e-9);
  // with the momentum p kept, the motion of the center of mass keeps p²/(2 Σm) = 1/10 J: no
  // collision response can take more (the perfectly plastic end, all five at 1/5 m/s)
  const double plastic = p0.squaredNorm() / (2.0 * 5.0);
  CHECK(e1 >= plastic - 1e-9);
  // Measured: KE_end = 0.10013563840567402 J, the balls at 0.1874, 0.1961, 0.2031, 0.2067, 0.2067 m/s.
  // The striker arrives at exactly 1 m/s, which is not faster than kRestitutionThreshold (1 m/s;
  // restitution needs v_n < −1): the solver treats the impact as plastic (no bias), and the
  // converged plastic answer for a row of touching balls is all five moving together at p/(5m) =
  // 0.2 m/s, KE = 0.1 J. The sequential solver distributes the impulse over the chain at once by
  // 8 Gauss–Seidel sweeps per step, which do not fully converge along a row of four contacts: the
  // balls ahead are left slightly faster than the ones behind, the contacts open, and the row
  // spreads apart with a little more than the plastic minimum. Nothing like the ideal cradle
  // (0.5 J, only the last ball moving), which needs restitution applied contact by contact.
}

namespace {

const sim::core::Integrator kIntegrators[] = {sim::core::Integrator::ExplicitEuler, sim::core::Integrator::SymplecticEuler,
                                              sim::core::Integrator::Midpoint, sim::core::Integrator::Rk4};

// `count` 1 m boxes resting on a plane (the lowest touching it, each on the one below) under
// `integrator` at `dt`, friction 0.5
std::string restingColumn(sim::core::Integrator integrator, double dt, int count) {
  std::string s = "world: {gravity: [0, -9.81], friction: 0.5}\nsim: {collisions: sequential, integrator: " +
                  std::string(sim::core::integratorName(integrator)) + ", dt: " + num(dt) +
                  "}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int i = 0; i < count; ++i)
    s += "  - {name: b" + std::to_string(i) + ", shape: {box: [1, 1]}, position: " + vec(0, 0.5 + i) + "}\n";
  return s;
}

}  // namespace

// The contact impulse over a step is a force held for the step, moved as the integrator moves a
// constant force (integratePositions): a resting body stays, where moving it by h Δv under RK4 or
// the midpoint rule lifted it by ½ h² g a step (4 mm above the floor, moving at 0.04 m/s)
TEST_CASE("sequential: a box and a column of five at rest stay at rest under every integrator") {
  for (const sim::core::Integrator integrator : kIntegrators)
    for (const double dt : {0.001, 1.0 / 60.0})
      for (const int count : {1, 5}) {
        CAPTURE(sim::core::integratorName(integrator));
        CAPTURE(dt);
        CAPTURE(count);
        sim::world::World w = build(restingColumn(integrator, dt, count));
        w.advanceTo(2.0);
        for (int i = 0; i < count; ++i) {
          const sim::core::Body& b = w.bodies[1 + i];
          CHECK(b.v.norm() + std::abs(b.omega) <= 1e-9);
          // each box on the one below: its height within the slop a contact leaves per box
          CHECK(std::abs(b.x.y() - (0.5 + i)) <= sim::core::settings::kLinearSlop * (i + 1));
        }
      }
}

// a box launched along a rough floor stops after v²/(2μg) with the integrator's own lag: symplectic
// Euler's positions take each step's end velocity (h v₀/2 short), explicit Euler's its start's
// (h v₀/2 long), the midpoint rule and RK4 the trapezoid, exact under a constant deceleration; the
// stop falls within a step, which leaves μ g h² more either way
TEST_CASE("sequential: a box sliding to a stop stops at v²/(2μg) within its integrator's lag") {
  const double v0 = 2.0, mu = 0.3, g = 9.81, stop = v0 * v0 / (2.0 * mu * g);
  for (const sim::core::Integrator integrator : kIntegrators)
    for (const double dt : {0.001, 1.0 / 60.0}) {
      CAPTURE(sim::core::integratorName(integrator));
      CAPTURE(dt);
      sim::world::World w = build("world: {gravity: [0, -9.81]}\nsim: {collisions: sequential, integrator: " +
                                  std::string(sim::core::integratorName(integrator)) + ", dt: " + num(dt) +
                                  "}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
                                  "  - {name: box, shape: {box: [1, 0.5]}, position: [0, 0.25], velocity: [2, 0], friction: " +
                                  num(mu) + "}\n");
      w.advanceTo(2.0);
      const double lag = integrator == sim::core::Integrator::SymplecticEuler ? -0.5 * dt * v0
                         : integrator == sim::core::Integrator::ExplicitEuler ? 0.5 * dt * v0
                                                                              : 0.0;
      CHECK(w.bodies[1].v.norm() <= 1e-9);
      CHECK(std::abs(w.bodies[1].x.x() - (stop + lag)) <= mu * g * dt * dt);
      CHECK(std::abs(w.bodies[1].x.y() - 0.25) <= 1e-9);
    }
}

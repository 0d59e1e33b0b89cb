// The `event` method (event_stepper.cpp): exact times of impact, the notes' impulse at each, no
// tunneling, simultaneous impacts, Zeno bounces turned into resting contact.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"
#include "support/scene_text.h"

namespace {

using namespace scene_text;

// checks after every finished step: Σ m v and Σ x × m v + I ω about the origin stay what they were
class Conservation : public sim::world::StepObserver {
 public:
  explicit Conservation(const sim::world::World& w) : p0(sim::world::linearMomentum(w)), l0(sim::world::angularMomentum(w)) {}
  // impacts conserve both momenta exactly; once a contact rests (a Zeno pile-up turned into
  // resting contact), its overlap is projected away by moving the bodies apart, which keeps the
  // center of mass (and so p) but not the angular momentum: that part is recorded apart
  void afterStep(const sim::world::World& w) override {
    dp = std::max(dp, (sim::world::linearMomentum(w) - p0).norm());
    (w.resting.empty() ? dl : dlResting) =
        std::max(w.resting.empty() ? dl : dlResting, std::abs(sim::world::angularMomentum(w) - l0));
  }
  sim::core::Vec2 p0;
  double l0;
  double dp = 0.0, dl = 0.0, dlResting = 0.0;
};

// the fastest any material point of the scene moves at the start, m/s: Σ |v| + |ω| R
double speedScale(const sim::world::World& w) {
  double v = 0.0;
  for (const sim::core::Body& b : w.bodies)
    if (!b.isStatic) v += b.v.norm() + std::abs(b.omega) * sim::core::boundingRadius(b.shape);
  return v;
}

// every logged impulse of a frictionless contact obeys v_n⁺ = −c_r v_n⁻ to 1e-12 relative.
// v_n is a difference of point velocities of size `speed`, so it carries a round-off of about
// 1e-16 `speed` whatever its own size: for impacts far slower than the bodies' motion (|v_n| below
// 1e-4 `speed`) the bound is that absolute floor (1e-14 `speed`, a hundred ulps) instead. (Such
// impulses, 1e-5 to 1e-8 m/s between bodies moving at m/s, appear here only in the pile-ups of the
// free-space Zeno failure below.) For a body on a static floor without spin (speed = 0) v_n is the
// body's velocity and no floor is needed.
void checkRestitutionLaw(const sim::world::World& w, double cr, double speed = 0.0) {
  for (const sim::world::ImpactRecord& r : w.impacts) {
    CAPTURE(r.t);
    CAPTURE(r.vnBefore);
    CAPTURE(r.vnAfter);
    CHECK(r.vnBefore < 0.0);
    CHECK(std::abs(r.vnAfter + cr * r.vnBefore) <= std::max(1e-12 * std::abs(r.vnBefore), 1e-14 * speed));
  }
}

struct RunResult {
  size_t impacts = 0;
  bool threw = false;
};

// run a free-space scene without friction or gravity and check the laws the event method keeps
// (on whatever it logged, also when the run stops with an error, which is itself a failure)
RunResult runFreeScene(const std::string& yaml, double cr, double until) {
  sim::world::World w = build(yaml);
  REQUIRE(w.def().forces.gravity == sim::core::Vec2::Zero());
  const double e0 = sim::world::energy(w).kinetic, speed = speedScale(w);
  Conservation obs(w);
  bool threw = false;
  try {
    w.advanceTo(until, &obs);
  } catch (const std::runtime_error& e) {
    threw = true;
    FAIL_CHECK("the event method stopped at t = " << w.time << " after " << w.impacts.size()
                                                  << " impulses: " << std::string(e.what()));
  }
  CHECK(w.collisions() == sim::core::CollisionMethod::Event);
  checkRestitutionLaw(w, cr, speed);
  CHECK(obs.dp <= 1e-9);
  CHECK(obs.dl <= 1e-9);
  if (cr == 1.0) CHECK(std::abs(sim::world::energy(w).kinetic - e0) <= 1e-9 * std::max(1.0, e0));
  // never more energy than before: every impulse takes (1 − c_r²) of the normal part away
  CHECK(sim::world::energy(w).kinetic <= e0 * (1.0 + 1e-12));
  return {w.impacts.size(), threw};
}

}  // namespace

TEST_CASE("off-center box–bar impacts (two_bodies) with random velocities and angles obey the notes' law") {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  size_t impacts = 0;
  for (int k = 0; k < 24; ++k) {
    // every fourth run elastic, the others with a random c_r in [0, 1]
    const double cr = k % 4 == 0 ? 1.0 : unit(rng);
    // the box (0.6 m, 2 kg) left of the bar (0.2 × 2 m, 1 kg), sliding at it off-center
    const double y = 0.8 * u(rng), angle = 3.0 * u(rng);
    const double vx = 2.0 + u(rng), vy = 0.3 * u(rng), omega = 2.0 * u(rng);
    const double barAngle = 0.5 * u(rng), barVx = 0.3 * u(rng), barVy = 0.3 * u(rng), barOmega = u(rng);
    const std::string yaml = "world: {restitution: " + num(cr) +
                             "}\n"
                             "sim: {collisions: event, dt: 0.01}\n"
                             "bodies:\n"
                             "  - {name: box, shape: {box: [0.6, 0.6]}, mass: 2, position: " +
                             vec(-1.5, y) + ", angle: " + num(angle) + ", velocity: " + vec(vx, vy) +
                             ", angular_velocity: " + num(omega) +
                             "}\n"
                             "  - {name: bar, shape: {box: [0.2, 2.0]}, mass: 1, position: [0, 0], angle: " +
                             num(barAngle) + ", velocity: " + vec(barVx, barVy) + ", angular_velocity: " + num(barOmega) + "}\n";
    CAPTURE(yaml);
    impacts += runFreeScene(yaml, cr, 3.0).impacts;
  }
  CHECK(impacts >= 24);
}

TEST_CASE("random polygon and circle pairs in free space, random c_r: restitution law and conservation") {
  std::mt19937_64 rng(31415);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  size_t impacts = 0;
  int struck = 0;
  for (int k = 0; k < 30; ++k) {
    const double cr = k % 3 == 0 ? 1.0 : unit(rng);
    const std::string a = randomBody(rng, "a", -2.0, 2.0, 1.0);
    const std::string b = randomBody(rng, "b", 2.0, -0.5, 0.5);
    const std::string yaml = "world: {restitution: " + num(cr) + "}\nsim: {collisions: event, dt: 0.01}\nbodies:\n" + a + b;
    CAPTURE(yaml);
    const RunResult r = runFreeScene(yaml, cr, 5.0);
    impacts += r.impacts;
    struck += r.impacts > 0;
  }
  // the bodies are aimed at each other: nearly every run has an impact
  CHECK(struck >= 25);
  MESSAGE("random pairs: " << struck << " of 30 runs collided, " << impacts << " impulses checked");
}

TEST_CASE("free space, c_r < 1: spinning bodies that press together without any force do not stop the run") {
  // Found by the random box–bar runs above (c_r = 0.343). After the first impact the box's corner
  // chatters on the bar's face: each impulse leaves at c_r v_n⁻ and the corner comes back, the
  // flights shrinking by c_r each time (Zeno), because the two spinning bodies' free motion
  // accelerates the corner into the face (a relative normal acceleration of a few m/s², from the
  // rotation alone: there is no force in the scene). The sum of the flights is finite, so the
  // contact must become persistent there, as the bouncing ball's does under gravity.
  const char* yaml = R"(
world: {restitution: 0.34290821511990971}
sim: {collisions: event, dt: 0.01}
bodies:
  - {name: box, shape: {box: [0.6, 0.6]}, mass: 2, position: [-1.5, -0.12955106784284576], angle: 0.91574993024862206, velocity: [2.3335264101545157, 0.067575538986505673], angular_velocity: 0.86171857721428813}
  - {name: bar, shape: {box: [0.2, 2.0]}, mass: 1, position: [0, 0], angle: -0.35009844106800936, velocity: [0.097110969544626946, 0.26842346757026464], angular_velocity: -0.045220132625901188}
)";
  sim::world::World w = build(yaml);
  Conservation obs(w);
  try {
    w.advanceTo(3.0, &obs);
  } catch (const std::runtime_error& e) {
    // where it stopped: the pair touching, the gap over the next τ of free motion −½ a τ²
    const sim::core::Body &a = w.bodies[0], &b = w.bodies[1];
    auto freeGap = [&](double tau) {
      const sim::core::Pose pa{a.x + tau * a.v, sim::core::Rot::fromAngle(a.angle + tau * a.omega)};
      const sim::core::Pose pb{b.x + tau * b.v, sim::core::Rot::fromAngle(b.angle + tau * b.omega)};
      return sim::collision::collide(a.shape, pa, b.shape, pb, 0.0).separation;
    };
    const double tau = 1e-3, pressing = -2.0 * (freeGap(tau) - freeGap(0.0)) / (tau * tau);
    const sim::world::ImpactRecord& last = w.impacts.back();
    FAIL_CHECK("the event method gave up at t = " << num(last.t) << " after " << w.impacts.size()
                                                  << " impulses (the last with v_n⁻ = " << last.vnBefore << " m/s); gap now "
                                                  << freeGap(0.0) << " m, free motion presses the pair together at " << pressing
                                                  << " m/s²; error: " << std::string(e.what()));
  }
  checkRestitutionLaw(w, 0.34290821511990971, speedScale(build(yaml)));
  CHECK(obs.dp <= 1e-9);
  CHECK(obs.dl <= 1e-9);
  // the pile-up became resting contact, which held the two together without overlap
  CHECK_FALSE(w.resting.empty());
  MESSAGE("angular momentum change while resting (position projection): " << obs.dlResting);
}

namespace {

// c_r = 0.8, ball r = 0.2 with its center dropped from 1.0 onto a plane floor, g = 9.81
const char* kBouncingBall = R"(
world: {gravity: [0, -9.81], restitution: 0.8}
sim: {collisions: event}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: ball, shape: {circle: 0.2}, density: 10, position: [0, 1.0]}
)";

class BallWatch : public sim::world::StepObserver {
 public:
  double lowest = 1e300;
  double restingDrift = 0.0;  // after resting: largest |y − 0.2| and |v|
  void afterStep(const sim::world::World& w) override {
    const sim::core::Body& ball = w.bodies[1];
    lowest = std::min(lowest, ball.x.y());
    if (!w.resting.empty() && w.time > w.resting[0].t)
      restingDrift = std::max({restingDrift, std::abs(ball.x.y() - 0.2), ball.v.norm(), std::abs(ball.omega)});
  }
};

}  // namespace

TEST_CASE("bouncing ball: apexes fall by c_r², rest at t₀(1 + c_r)/(1 − c_r), then lie still on the floor") {
  const double g = 9.81, cr = 0.8, h0 = 0.8;  // h0: the drop height of the center above resting (0.2)
  const double t0 = std::sqrt(2.0 * h0 / g);  // the first impact
  sim::world::World w = build(kBouncingBall);
  BallWatch watch;

  // closed form: impact k (k = 0, 1, ...) at T_k = t₀ + 2 t₀ (c_r + … + c_rᵏ), leaving at c_rᵏ⁺¹ g t₀;
  // the apex after it at T_k + c_rᵏ⁺¹ t₀, h0 c_r²⁽ᵏ⁺¹⁾ above the resting height
  const int kApexes = 12;
  std::vector<double> sampled;
  double impactTime = t0, rebound = cr;
  for (int k = 0; k < kApexes; ++k) {
    const double apexTime = impactTime + rebound * t0;
    w.advanceTo(apexTime, &watch);
    const sim::core::Body& ball = w.bodies[1];
    sampled.push_back(ball.x.y() - 0.2);
    CAPTURE(k);
    // at the apex the vertical velocity is zero (the predicted time is right)
    CHECK(std::abs(ball.v.y()) <= 1e-9);
    CHECK(sampled[k] == doctest::Approx(h0 * rebound * rebound).epsilon(1e-9));
    if (k > 0) CHECK(sampled[k] / sampled[k - 1] == doctest::Approx(cr * cr).epsilon(1e-9));
    impactTime += 2.0 * rebound * t0;
    rebound *= cr;
  }
  w.advanceTo(5.0, &watch);

  // the same apexes from the logged impacts: the ball leaves impact k at v_k = vn_after, and rises
  // v_k²/(2g); consecutive apexes differ by c_r²
  REQUIRE(w.impacts.size() > static_cast<size_t>(kApexes));
  for (int k = 0; k < kApexes; ++k) {
    const sim::world::ImpactRecord& r = w.impacts[k];
    const double apex = r.vnAfter * r.vnAfter / (2.0 * g);
    CAPTURE(k);
    CHECK(apex == doctest::Approx(sampled[k]).epsilon(1e-9));
    if (k > 0) {
      const double previous = w.impacts[k - 1].vnAfter * w.impacts[k - 1].vnAfter / (2.0 * g);
      CHECK(apex / previous == doctest::Approx(cr * cr).epsilon(1e-9));
    }
  }
  checkRestitutionLaw(w, cr);

  // Zeno: the flights 2 c_rᵏ t₀ sum to the rest time t₀ + 2 t₀ c_r/(1 − c_r) = t₀ (1 + c_r)/(1 − c_r).
  // The method stops the series at the first bounce leaving slower than kRestingSpeed: the
  // flights it leaves out add up to 2 v_N/(g (1 − c_r)) ≤ 2 kRestingSpeed/(g (1 − c_r)) ≈ 1.02e-6 s,
  // so the recorded time is at most that early (and never late beyond round-off).
  REQUIRE(w.resting.size() == 1);
  // the ball lies still on the floor: it came to rest
  CHECK_FALSE(w.resting[0].moving);
  const double zeno = t0 * (1.0 + cr) / (1.0 - cr);
  const double neglected = 2.0 * sim::core::settings::kRestingSpeed / (g * (1.0 - cr));
  REQUIRE(neglected < 2e-6);
  MESSAGE("bouncing ball: " << w.impacts.size() << " impacts, resting at " << num(w.resting[0].t) << " s, Zeno limit "
                            << num(zeno) << " s, difference " << zeno - w.resting[0].t << " s");
  CHECK(std::abs(w.resting[0].t - zeno) <= 2e-6);
  CHECK(w.resting[0].t <= zeno + 1e-9);
  CHECK(w.resting[0].t >= zeno - neglected - 1e-9);
  CHECK(w.resting[0].a == 0);
  CHECK(w.resting[0].b == 1);

  // at rest on the floor up to t = 5, and never below it at any step
  const sim::core::Body& ball = w.bodies[1];
  CHECK(w.time == 5.0);
  CHECK(std::abs(ball.x.y() - 0.2) <= 1e-9);
  CHECK(ball.v.norm() <= 1e-9);
  CHECK(watch.restingDrift <= 1e-9);
  CHECK(watch.lowest >= 0.2 - 1e-9);
}

namespace {

// a thin body (5 cm) toward a thin static wall (5 cm), c_r = 1, dt = 1/60: the faces are
// 1 − 0.025 − 0.025 = 0.95 m apart at the start
std::string tunneling(double speed, const char* method) {
  return std::string("world: {restitution: 1}\nsim: {collisions: ") + method +
         ", dt: 0.016666666666666667}\n"
         "bodies:\n"
         "  - {name: wall, shape: {box: [0.05, 2.0]}, static: true}\n"
         "  - {name: bullet, shape: {box: [0.05, 0.2]}, mass: 0.1, position: [-1, 0], velocity: " +
         vec(speed, 0) + "}\n";
}

class WallWatch : public sim::world::StepObserver {
 public:
  double closest = 1e300;  // the smallest separation of bullet and wall at any step end
  void afterStep(const sim::world::World& w) override {
    const sim::core::Body &wall = w.bodies[0], &bullet = w.bodies[1];
    closest = std::min(closest, sim::collision::collide(wall.shape, wall.pose(), bullet.shape, bullet.pose(), 0.0).separation);
  }
};

}  // namespace

TEST_CASE("the event method never tunnels, and its times of impact are exact") {
  for (double speed : {10.0, 100.0, 1e3, 1e4, 1e5}) {
    CAPTURE(speed);
    sim::world::World w = build(tunneling(speed, "event"));
    WallWatch watch;
    const double toi = 0.95 / speed;  // the gap over the speed
    w.advanceTo(toi + 3.0 / 60.0, &watch);
    const sim::core::Body& bullet = w.bodies[1];
    // bounced straight back at the same speed (c_r = 1, a head-on impact on a flat face)
    CHECK(bullet.v.x() == doctest::Approx(-speed).epsilon(1e-12));
    CHECK(std::abs(bullet.v.y()) <= 1e-12 * speed);
    CHECK(std::abs(bullet.omega) <= 1e-12 * speed);
    CHECK(bullet.x.x() < -0.05);
    // no step ever ended with the bodies overlapping
    CHECK(watch.closest >= 0.0);
    // the time of impact: every impulse of the impact at exactly gap/speed
    REQUIRE(!w.impacts.empty());
    for (const sim::world::ImpactRecord& r : w.impacts) CHECK(r.t == doctest::Approx(toi).epsilon(1e-12));
    // the face met the face: both manifold points at x = −0.025
    for (const sim::world::ImpactRecord& r : w.impacts) CHECK(std::abs(r.point.x() + 0.025) <= 1e-12);
  }
}

TEST_CASE("Newton's cradle under event: the last ball leaves at the striker's speed, the others rest") {
  const scene_text::CradleRun r = scene_text::runCradle(sim::core::CollisionMethod::Event);
  const sim::world::World& w = r.world;
  const sim::core::Vec2 p0 = r.p0;
  const double e0 = r.e0;
  // b1 reaches b2 at t = 2 (it covers 2 m at 1 m/s); b5 then moves 1 m by t = 3
  for (int i = 0; i < 4; ++i) {
    CAPTURE(i);
    CHECK(w.bodies[i].v.norm() <= 1e-9);
  }
  CHECK((w.bodies[4].v - sim::core::Vec2(1, 0)).norm() <= 1e-9);
  CHECK((w.bodies[4].x - sim::core::Vec2(5, 0)).norm() <= 1e-9);
  CHECK((w.bodies[0].x - sim::core::Vec2(0, 0)).norm() <= 1e-9);
  CHECK((sim::world::linearMomentum(w) - p0).norm() <= 1e-9);
  CHECK(std::abs(sim::world::energy(w).kinetic - e0) <= 1e-9);
  checkRestitutionLaw(w, 1.0);
  MESSAGE("cradle, event: kinetic energy " << num(e0) << " J -> " << num(sim::world::energy(w).kinetic) << " J");
}

TEST_CASE("bodies overlapping at t = 0 under event: start() throws InitialOverlap naming the pair and the depth") {
  // boxes of 1 m at (0, 0) and (0.9, 0.2): they overlap by 1 − 0.9 = 0.1 along x (0.8 along y);
  // body 0, far away, is not part of it
  sim::world::World boxes = build(R"(
sim: {collisions: event}
bodies:
  - {name: far, shape: {circle: 0.5}, position: [10, 10]}
  - {name: a, shape: {box: [1, 1]}, position: [0, 0]}
  - {name: b, shape: {box: [1, 1]}, position: [0.9, 0.2]}
)");
  try {
    boxes.start();
    FAIL("no InitialOverlap");
  } catch (const sim::world::InitialOverlap& e) {
    CHECK(e.a == 1);
    CHECK(e.b == 2);
    CHECK(e.depth == doctest::Approx(0.1).epsilon(1e-12));
  }

  // circles of radius 0.5 and 0.3 with centers 0.6 apart: depth 0.5 + 0.3 − 0.6 = 0.2
  sim::world::World circles = build(R"(
sim: {collisions: event}
bodies:
  - {name: a, shape: {circle: 0.5}, position: [0, 0]}
  - {name: b, shape: {box: [4, 0.2]}, position: [0, 5]}
  - {name: c, shape: {circle: 0.3}, position: [0.36, 0.48]}
)");
  try {
    circles.advanceTo(1.0);
    FAIL("no InitialOverlap");
  } catch (const sim::world::InitialOverlap& e) {
    CHECK(e.a == 0);
    CHECK(e.b == 2);
    CHECK(e.depth == doctest::Approx(0.2).epsilon(1e-12));
  }

  // touching exactly is not an overlap: the event method starts there
  sim::world::World touching = build(R"(
sim: {collisions: event}
bodies:
  - {name: a, shape: {box: [1, 1]}, position: [0, 0]}
  - {name: b, shape: {box: [1, 1]}, position: [1, 0.3]}
)");
  CHECK_NOTHROW(touching.start());
}

TEST_CASE("a plastic contact that keeps turning while it touches stays in contact; it does not come to rest") {
  // the lecture's body-obstacle collision, plastic: the bar lands on a corner, spins down and lies on
  // the floor while it still slides and turns
  sim::world::World w = build(R"(
world: {restitution: 0}
sim: {collisions: event}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: bar, shape: {box: [2.0, 0.2]}, mass: 1, position: [0, 1.3910538555739002], angle: 0.3, velocity: [0, -2]}
)");
  w.advanceTo(1.2);
  REQUIRE_FALSE(w.resting.empty());
  for (const sim::world::RestingRecord& r : w.resting) CHECK(r.moving);
}

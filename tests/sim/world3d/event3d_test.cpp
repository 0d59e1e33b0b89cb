// The 3D `event` method (event3d.cpp): exact isolated impacts against the closed forms, and where it
// stops (a contact that persists), which `auto` hands to sequential.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/core/energy_ledger_of.h"
#include "sim/world3d/diagnostics.h"
#include "sim/world3d/energy_ledger3d.h"
#include "sim/world3d/world.h"
#include "support/redefined.h"

using namespace sim::world3d;
using sim::core::CollisionMethod;

namespace {
constexpr double kG = 9.81;

World onFloor(CollisionMethod method, double restitution, double friction = 0.0) {
  WorldDef def;
  def.planes.push_back({Vec3::Zero(), Vec3::UnitZ(), restitution, friction, friction > 0.0});
  def.forces.gravity = Vec3(0, 0, -kG);
  def.collisions = method;
  return World(def);
}
}  // namespace

TEST_CASE("a ball dropped from h rebounds to c_r² h, at the time of the closed form, to round-off") {
  for (const double cr : {1.0, 0.8, 0.3}) {
    CAPTURE(cr);
    World w = onFloor(CollisionMethod::Event, cr);
    Body ball = makeBody(makeSphere(0.1), 1.0 / (4.0 / 3.0 * M_PI * 0.001));
    ball.restitution = cr;
    const double h = 1.0;
    ball.x = Vec3(0, 0, 0.1 + h);
    w.bodies.push_back(ball);
    EnergyLedger3d ledger(w);
    // it lands at √(2h/g) and is at its apex c_r √(2gh)/g later
    const double land = std::sqrt(2 * h / kG), apex = land + cr * std::sqrt(2 * kG * h) / kG;
    w.advanceTo(apex, &ledger);
    CHECK(w.bodies[0].x.z() == doctest::Approx(0.1 + cr * cr * h).epsilon(1e-12));
    CHECK(std::abs(w.bodies[0].v.z()) <= 1e-12);
    REQUIRE(w.impacts.size() == 1);
    CHECK(w.impacts[0].t == doctest::Approx(land).epsilon(1e-12));
    CHECK(w.impacts[0].vnAfter == doctest::Approx(-cr * w.impacts[0].vnBefore).epsilon(1e-12));
    // it lost ½ m v² (1 − c_r²) at the impact, and nothing rose
    CHECK(ledger.lostAtImpacts == doctest::Approx(ball.mass * kG * h * (1 - cr * cr)).epsilon(1e-9));
    CHECK(ledger.largestRise().amount <= 1e-12);
  }
}

TEST_CASE("a box landing flat on its face with no spin rebounds as a point mass") {
  World w = onFloor(CollisionMethod::Event, 0.7, 0.5);
  Body box = makeBody(makeBox(Vec3(0.4, 0.3, 0.2)), 50.0);
  box.restitution = 0.7;
  box.x = Vec3(0, 0, 0.6);
  w.bodies.push_back(box);
  const double vLand = std::sqrt(2 * kG * 0.5);
  w.advanceTo(0.5);
  // its four lower corners struck together: one bounce, no spin, v_z⁺ = c_r v_land
  REQUIRE(w.impacts.size() == 4);
  CHECK(w.bodies[0].omega.norm() <= 1e-12);
  CHECK(w.bodies[0].v.head<2>().norm() <= 1e-12);
  const double t = std::sqrt(2 * 0.5 / kG);
  CHECK(w.bodies[0].v.z() == doctest::Approx(0.7 * vLand - kG * (0.5 - t)).epsilon(1e-12));
  for (const ImpactRecord3& r : w.impacts) CHECK(r.vnAfter == doctest::Approx(-0.7 * r.vnBefore).epsilon(1e-12));
}

TEST_CASE("two spheres: the notes' two-body impulse in 3D keeps momentum, and c_r = 1 the kinetic energy") {
  WorldDef def;
  def.collisions = CollisionMethod::Event;
  World w(def);
  Body a = makeBody(makeSphere(0.5), 1.0), b = makeBody(makeSphere(0.3), 3.0);
  a.restitution = b.restitution = 1.0;
  a.x = Vec3(-2, 0.2, 0.1), a.v = Vec3(2, 0, 0), a.omega = Vec3(0, 0, 5);
  b.x = Vec3(0, 0, 0), b.v = Vec3(-0.5, 0, 0);
  w.bodies = {a, b};
  const Vec3 p0 = linearMomentum(w), l0 = angularMomentum(w);
  const double e0 = energy(w).kinetic;
  w.advanceTo(2.0);
  REQUIRE(w.impacts.size() == 1);
  CHECK((linearMomentum(w) - p0).norm() <= 1e-12);
  CHECK((angularMomentum(w) - l0).norm() <= 1e-12);
  CHECK(energy(w).kinetic == doctest::Approx(e0).epsilon(1e-12));
  CHECK(w.impacts[0].vnAfter == doctest::Approx(-w.impacts[0].vnBefore).epsilon(1e-12));
}

TEST_CASE("event named stops where a contact persists; under auto, sequential takes over from that step") {
  // a ball bouncing to rest: its Zeno series ends in a contact too slow to part
  auto bouncing = [](CollisionMethod method) {
    World w = onFloor(method, 0.5);
    Body ball = makeBody(makeSphere(0.1), 100.0);
    ball.restitution = 0.5;
    ball.x = Vec3(0, 0, 0.3);
    w.bodies.push_back(ball);
    return w;
  };
  World named = bouncing(CollisionMethod::Event);
  CHECK_THROWS_AS(named.advanceTo(3.0), ContactPersists);
  World automatic = bouncing(CollisionMethod::Auto);
  automatic.start();
  CHECK(automatic.collisions() == CollisionMethod::Event);
  automatic.advanceTo(3.0);
  CHECK(automatic.collisions() == CollisionMethod::Sequential);
  REQUIRE(automatic.methodSwitch());
  CHECK(automatic.methodSwitch()->a == 0);
  CHECK(automatic.methodSwitch()->b == -1);
  CHECK(automatic.methodSwitch()->time < 1.5);
  CHECK(automatic.bodies[0].v.norm() <= 1e-9);
  CHECK(automatic.bodies[0].x.z() == doctest::Approx(0.1).epsilon(sim::core::settings::kLinearSlop));
}

TEST_CASE("a pair touching and approaching strikes at once; one resting under gravity persists, never jitters") {
  // no gravity: a ball on the floor moving into it bounces at t = 0, not 0.5 mm into the floor
  World w = onFloor(CollisionMethod::Event, 1.0);
  w = fixtures::redefined(w, [&](auto& d) { d.forces.gravity = Vec3::Zero(); });
  Body ball = makeBody(makeSphere(0.1), 100.0);
  ball.restitution = 1.0;
  ball.x = Vec3(0, 0, 0.1), ball.v = Vec3(0, 0, -1);
  w.bodies.push_back(ball);
  w.advanceTo(0.01);
  REQUIRE(w.impacts.size() == 1);
  CHECK(w.impacts[0].t <= 1e-12);
  CHECK(w.bodies[0].v.z() == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(w.bodies[0].x.z() == doctest::Approx(0.1 + 0.01).epsilon(1e-12));
  // under gravity at rest on the floor: named event stops there, at the first step
  World resting = onFloor(CollisionMethod::Event, 0.5);
  Body still = makeBody(makeSphere(0.1), 100.0);
  still.x = Vec3(0, 0, 0.1);
  resting.bodies.push_back(still);
  try {
    resting.advanceTo(1.0);
    FAIL("a ball at rest on the floor under event should persist");
  } catch (const ContactPersists& e) {
    CHECK(e.time <= resting.def().dt);
  }
}

TEST_CASE("a box landing flat while it slides is stopped alike at every corner: no roll about its sliding axis") {
  World w = onFloor(CollisionMethod::Event, 0.7, 0.05);
  Body box = makeBody(makeBox(Vec3(0.4, 0.3, 0.2)), 50.0);
  box.restitution = 0.7, box.friction = 0.05;
  box.x = Vec3(0, 0, 0.6), box.v = Vec3(1, 0, 0);
  w.bodies.push_back(box);
  EnergyLedger3d ledger(w);
  w.advanceTo(0.35, &ledger);
  REQUIRE(w.impacts.size() == 4);
  // friction against +x at the face's centre turns it about y alone
  CHECK(std::abs(w.bodies[0].omega.x()) <= 1e-12);
  CHECK(std::abs(w.bodies[0].omega.z()) <= 1e-12);
  CHECK(std::abs(w.bodies[0].v.y()) <= 1e-12);
  // the whole patch's cone: Σ|j_t| ≤ μ Σγ, and on so light a friction it slid on, so equal
  double normal = 0.0, tangent = 0.0;
  for (const ImpactRecord3& r : w.impacts) normal += r.impulse, tangent += r.tangentImpulse.norm();
  CHECK(tangent == doctest::Approx(0.05 * normal).epsilon(1e-12));
  CHECK(w.bodies[0].v.x() == doctest::Approx(1.0 - 0.05 * normal / w.bodies[0].mass).epsilon(1e-12));
  CHECK(ledger.largestRise().amount <= 1e-12);
}

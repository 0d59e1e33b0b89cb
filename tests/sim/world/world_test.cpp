#include "sim/world/world.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/yaml/scene_yaml.h"

namespace {

// the notes' poll: bar l = 4, m = 3, I = 4, j = (1, 0) at the center or at the end
const char* kPoll = R"(
duration: 2
sim: {integrator: rk4, dt: 0.001}
bodies:
  - {name: bar, shape: {box: [0.2, 4.0]}, mass: 3, inertia: 4}
events:
  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}
variants:
  center: {events: [{time: 0.5, body: bar, impulse: [1, 0], point: [0, 0]}]}
  end: {}
)";

sim::world::World poll(const std::string& variant, sim::core::Integrator method) {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(kPoll, "inline.yaml", variant);
  def.integrator = method;
  return sim::scene::buildWorld(def);
}

class Recorder : public sim::world::StepObserver {
 public:
  std::vector<double> stepTimes, eventTimes;
  void afterStep(const sim::world::World& w) override { stepTimes.push_back(w.time); }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent&) override { eventTimes.push_back(w.time); }
};

}  // namespace

TEST_CASE("the notes' poll, both variants, exactly, with every integrator") {
  for (sim::core::Integrator m : {sim::core::Integrator::ExplicitEuler, sim::core::Integrator::SymplecticEuler,
                                  sim::core::Integrator::Midpoint, sim::core::Integrator::Rk4}) {
    CAPTURE(sim::core::integratorName(m));
    sim::world::World center = poll("center", m);
    center.advanceTo(1.0);
    CHECK(center.bodies[0].v.x() == 1.0 / 3.0);
    CHECK(center.bodies[0].v.y() == 0.0);
    CHECK(center.bodies[0].omega == 0.0);
    CHECK(sim::world::kineticEnergy(center.bodies[0]).total() == doctest::Approx(1.0 / 6.0).epsilon(1e-15));

    sim::world::World end = poll("end", m);
    end.advanceTo(1.0);
    CHECK(end.bodies[0].v.x() == 1.0 / 3.0);
    CHECK(end.bodies[0].omega == -0.5);
    CHECK(sim::world::kineticEnergy(end.bodies[0]).translational == doctest::Approx(1.0 / 6.0).epsilon(1e-15));
    CHECK(sim::world::kineticEnergy(end.bodies[0]).rotational == 0.5);
    CHECK(sim::world::kineticEnergy(end.bodies[0]).total() == doctest::Approx(2.0 / 3.0).epsilon(1e-15));
    // the bar turned at ω = -0.5 for exactly the 0.5 s since the event
    CHECK(std::abs(end.bodies[0].angle - (-0.25)) < 1e-13);
  }
}

TEST_CASE("steps are split exactly at events, force switches and the end time, and keep the grid") {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
duration: 1
sim: {dt: 0.1}
bodies: [{name: b, shape: {circle: 1}}]
forces: [{type: force, body: b, force: [1, 0], from: 0.25, until: 0.62}]
events: [{time: 0.33, body: b, impulse: [0, 1]}]
)",
                                                      "inline.yaml");
  sim::world::World w = sim::scene::buildWorld(def);
  Recorder r;
  w.advanceTo(0.75, &r);
  const std::vector<double> expected{0.1, 0.2, 0.25, 0.3, 0.33, 0.4, 0.5, 0.6, 0.62, 0.7, 0.75};
  REQUIRE(r.stepTimes.size() == expected.size());
  for (size_t i = 0; i < expected.size(); ++i) CHECK(r.stepTimes[i] == doctest::Approx(expected[i]).epsilon(1e-15));
  REQUIRE(r.eventTimes.size() == 1);
  CHECK(r.eventTimes[0] == 0.33);
  CHECK(w.time == 0.75);

  // the force acted for exactly 0.37 s on a unit-density circle of radius 1 (m = π)
  const double m = std::numbers::pi;
  CHECK(w.bodies[0].v.x() == doctest::Approx(0.37 / m).epsilon(1e-13));
  CHECK(w.bodies[0].v.y() == doctest::Approx(1 / m).epsilon(1e-14));
}

TEST_CASE("advanceWithin takes the run's own steps up to a time between them, never splitting one") {
  sim::world::World once = poll("end", sim::core::Integrator::Rk4), within = poll("end", sim::core::Integrator::Rk4);
  Recorder a, b;
  once.advanceTo(1.2345, &a);
  // pictures at 1/60 s (the event at 0.5 s is a step end of the run's own), the run's end 1.2345 s
  for (int k = 0; k < 75; ++k) within.advanceWithin(k / 60.0, 1.2345, &b);
  CHECK(within.time == doctest::Approx(1.233).epsilon(1e-12));
  within.advanceWithin(1.2345, 1.2345, &b);
  CHECK(within.time == 1.2345);
  CHECK(b.stepTimes == a.stepTimes);
  CHECK(b.eventTimes == a.eventTimes);
  CHECK(sim::world::stateHash(once) == sim::world::stateHash(within));
}

TEST_CASE("an impulse at a body point changes v by j/m and ω by I⁻¹ (r′ × j)") {
  sim::world::World w;
  sim::core::Body b;
  b.mass = 2, b.invMass = 0.5, b.inertia = 4, b.invInertia = 0.25;
  b.setState({{1, 1}, 0, {0, 0}, 0});
  w.bodies.push_back(b);
  w.applyImpulse(0, {1, 3}, {3, 0});
  CHECK(w.bodies[0].v == sim::core::Vec2(1.5, 0));
  // r′ = (0, 2), r′ × j = 0·0 − 2·3 = −6
  CHECK(w.bodies[0].omega == -1.5);
}

TEST_CASE("static bodies never move, whatever acts on them") {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
world: {gravity: [0, -10]}
bodies:
  - {name: ground, shape: {box: [10, 1]}, static: true, position: [0, -1]}
  - {name: ball, shape: {circle: 0.5}, position: [0, 2]}
forces: [{type: spring, body: ground, point: [0, 0], body2: ball, point2: [0, 0], stiffness: 100}]
events: [{time: 0.5, body: ground, impulse: [100, 100]}]
)",
                                                      "inline.yaml");
  sim::world::World w = sim::scene::buildWorld(def);
  w.advanceTo(1.0);
  CHECK(w.bodies[0].x == sim::core::Vec2(0, -1));
  CHECK(w.bodies[0].v == sim::core::Vec2(0, 0));
  CHECK(w.bodies[0].angle == 0.0);
  CHECK(w.bodies[1].x != sim::core::Vec2(0, 2));
}

TEST_CASE("a diverging simulation stops with the time and the body") {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
duration: 100
sim: {integrator: explicit_euler, dt: 0.1}
bodies: [{name: calm, shape: {circle: 1}}, {name: wild, shape: {circle: 1}, position: [2, 0]}]
forces: [{type: spring, body: wild, anchor: [0, 0], stiffness: 1e12}]
)",
                                                      "inline.yaml");
  sim::world::World w = sim::scene::buildWorld(def);
  try {
    w.advanceTo(100);
    FAIL("no divergence reported");
  } catch (const sim::core::Diverged& d) {
    CHECK(d.body == 1);
    CHECK(d.time > 0.0);
    CHECK(d.time < 100.0);
  }
}

namespace {

// Pinned state hashes (Box2D's determinism test: the hash of the final transforms stored as a
// constant). A change of any bit of any pose or velocity after N steps changes the hash, so every
// refactoring that claims "no change of behavior" is checked against the numbers of the code
// before it. They hold for this build (x86-64, glibc's libm, -ffp-contract=off); another libm's
// sin and cos may round differently, and then the constants are to be taken anew from a run of
// the code as it was.
struct Pinned {
  const char* name;
  const char* yaml;
  long steps;
  unsigned long long hash;
};

// a tilted stack with friction and a ball rolling onto it: warm starting, the 2×2 block solve,
// friction and the position pass, with bodies turning
const char* kStack = R"(
world: {gravity: [0, -10], friction: 0.6, restitution: 0.2}
sim: {collisions: sequential, dt: 0.01}
bodies:
  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: b1, shape: {box: [1, 1]}, position: [0, 0.5]}
  - {name: b2, shape: {box: [1, 1]}, position: [0.1, 1.52], angle: 0.05}
  - {name: b3, shape: {box: [1, 0.5]}, position: [-0.15, 2.3], angle: -0.1}
  - {name: ball, shape: {circle: 0.3}, position: [1.5, 3.0], velocity: [-1, 0]}
)";

// spinning bodies thrown at each other and at the floor: times of impact, simultaneous impacts,
// friction in the impulse, and contacts turned resting (the bouncing box settles)
const char* kCollisions = R"(
world: {gravity: [0, -9.81], restitution: 0.6, friction: 0.3}
sim: {collisions: event, dt: 0.01}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: box, shape: {box: [0.6, 0.4]}, position: [-0.8, 1.0], angle: 0.3, velocity: [1, 0], angular_velocity: 2}
  - {name: ball, shape: {circle: 0.25}, position: [0.7, 1.6], velocity: [-1, 0.5]}
  - {name: tri, shape: {polygon: [[0, 0], [0.5, 0], [0, 0.5]]}, position: [0, 2.5], angular_velocity: -3}
)";

// the notes' isolated impulses on fixed steps: a box dropped on a turned box on the floor
const char* kIsolated = R"(
world: {gravity: [0, -9.81], restitution: 0.4}
sim: {collisions: isolated, dt: 0.005}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: low, shape: {box: [1, 0.5]}, position: [0, 0.3], angle: 0.2}
  - {name: high, shape: {box: [0.4, 0.4]}, position: [0.2, 1.5], angular_velocity: 1}
)";

// free bodies under a spring, drag and a timed force that switches off inside the run, by rk4:
// the forces on at each of the integrator's stages
const char* kForces = R"(
world: {gravity: [0, -9.81]}
sim: {integrator: rk4, dt: 0.01}
bodies:
  - {name: bar, shape: {box: [0.1, 1.0]}, position: [0.3, -1.2], angle: 0.4}
  - {name: puck, shape: {circle: 0.2}, position: [1, 0], velocity: [0, 1]}
forces:
  - {type: spring, body: bar, point: [0, 0.5], anchor: [0, 0], stiffness: 40, rest_length: 0.5, damping: 0.3}
  - {type: force, body: puck, point: [0.2, 0], force: [0, 3], until: 0.505}
  - {type: drag, body: puck, linear: 0.2, angular: 0.1}
)";

}  // namespace

TEST_CASE("pinned state hashes after N steps: a stack (sequential), impacts (event), isolated, forces (rk4)") {
  const Pinned pinned[] = {
      {"stack", kStack, 300, 5430927149025592321ull},
      {"collisions", kCollisions, 300, 4991025036088471707ull},
      {"isolated", kIsolated, 400, 7426225104588946998ull},
      {"forces", kForces, 150, 17502462243100700567ull},
  };
  for (const Pinned& p : pinned) {
    const std::string name = p.name;
    CAPTURE(name);
    sim::world::World w = sim::scene::buildWorld(sim::yaml::loadSceneText(p.yaml, "inline.yaml"));
    while (w.steps < p.steps) w.advanceTo(w.time + w.def().dt);
    REQUIRE(w.steps == p.steps);
    CHECK(sim::world::stateHash(w) == p.hash);
  }
}

TEST_CASE("a copy of a world goes on exactly as the world would: the collision method's state is copied, not shared") {
  // mid-run under event, with contacts held at rest: the copy and the original, run one after the
  // other to the same time, end bit for bit alike
  sim::world::World original = sim::scene::buildWorld(sim::yaml::loadSceneText(kCollisions, "inline.yaml"));
  original.advanceTo(2.0);
  REQUIRE_FALSE(original.resting.empty());
  sim::world::World copy = original;
  original.advanceTo(3.0);
  copy.advanceTo(3.0);
  CHECK(sim::world::stateHash(copy) == sim::world::stateHash(original));
  CHECK(copy.impacts.size() == original.impacts.size());
}

namespace {

// Box2D's testbed pyramid, base 5: rows of 1 m boxes 0.25 m apart, dropped onto a ground box; no
// two bodies touch at the start, so `auto` begins with the event method
std::string droppedPile(const char* collisions) {
  std::string s = std::string("world: {gravity: [0, -10], friction: 0.6, restitution: 0}\nsim: {collisions: ") + collisions +
                  ", dt: 0.016666666666666667}\nbodies:\n"
                  "  - {name: ground, shape: {box: [40, 1]}, static: true, position: [0, -0.5]}\n";
  for (int r = 0; r < 5; ++r)
    for (int j = 0; j < 5 - r; ++j)
      s += "  - {name: b" + std::to_string(r) + std::to_string(j) + ", shape: {box: [1, 1]}, position: [" +
           std::to_string(-2.25 + 0.5625 * r + 1.125 * j) + ", " + std::to_string(0.75 + 1.25 * r) + "]}\n";
  return s;
}

}  // namespace

TEST_CASE("auto builds a stack: events until a contact persists, then the stack solver from that step on") {
  sim::world::World w = sim::scene::buildWorld(sim::yaml::loadSceneText(droppedPile("auto"), "inline.yaml"));
  std::vector<double> restX;
  for (const sim::core::Body& b : w.bodies) restX.push_back(b.x.x());
  w.start();
  CHECK(w.collisions() == sim::core::CollisionMethod::Event);
  CHECK_FALSE(w.methodSwitch());
  w.advanceTo(10.0);
  // the switch, reported: which method, why, between which bodies and from when (a step's end, as
  // the lowest row lands and rattles on the ground, before 1 s and before impacts pile up)
  CHECK(w.collisions() == sim::core::CollisionMethod::Sequential);
  CHECK(w.methodReason() == sim::core::MethodReason::ContactPersisted);
  REQUIRE(w.methodSwitch());
  CHECK(w.methodSwitch()->a == 0);
  CHECK(w.methodSwitch()->b >= 1);
  CHECK(w.methodSwitch()->time > 0.0);
  CHECK(w.methodSwitch()->time < 1.0);
  const double steps = w.methodSwitch()->time / w.def().dt;
  CHECK(std::abs(steps - std::round(steps)) < 1e-6);
  // the pile at rest, in place: every box slower than 1 cm/s and within 0.1 m of its rest x
  for (size_t i = 1; i < w.bodies.size(); ++i) {
    CAPTURE(i);
    CHECK(w.bodies[i].v.norm() < 0.01);
    CHECK(std::abs(w.bodies[i].omega) < 0.01);
    CHECK(std::abs(w.bodies[i].x.x() - restX[i]) < 0.1);
  }
  // no impact after the switch is the event method's: every later one is at a step's end
  for (const sim::world::ImpactRecord& r : w.impacts)
    if (r.t > w.methodSwitch()->time) CHECK(std::abs(r.t / w.def().dt - std::round(r.t / w.def().dt)) < 1e-6);
  for (const sim::world::RestingRecord& r : w.resting) CHECK(r.t <= w.methodSwitch()->time);

  // named explicitly, event keeps to itself and gives up as before
  sim::world::World event = sim::scene::buildWorld(sim::yaml::loadSceneText(droppedPile("event"), "inline.yaml"));
  CHECK_THROWS_AS(event.advanceTo(10.0), sim::world::ImpactsPileUp);
  CHECK(event.collisions() == sim::core::CollisionMethod::Event);
}

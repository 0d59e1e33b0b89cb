// Sleeping (sleep.cpp, sim: {sleep: true}): a settled pile falls asleep and then stays exactly where
// it is; a ball dropped on it, an impulse event or a force wakes it; until an island sleeps, and
// with sleep off, nothing changes by a bit.
#include "sim/world/sleep.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "sim/world/diagnostics.h"
#include "support/scene_text.h"
#include "support/redefined.h"

namespace {

using scene_text::build;

// a pyramid of six boxes on a long floor, and a ball high above that lands on its top at t ≈ 1.3 s
std::string pile(const std::string& method, const std::string& extra = "", bool ball = true) {
  return "duration: 10\nworld: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
         "sim: {collisions: " +
         method +
         ", dt: 0.016666666666666667, sleep: true}\n"
         "bodies:\n"
         "  - {name: floor, shape: {box: [200, 1]}, static: true, position: [0, -0.5]}\n"
         "  - {name: b0, shape: {box: [1, 1]}, position: [-1.1, 0.5]}\n"
         "  - {name: b1, shape: {box: [1, 1]}, position: [0, 0.5]}\n"
         "  - {name: b2, shape: {box: [1, 1]}, position: [1.1, 0.5]}\n"
         "  - {name: b3, shape: {box: [1, 1]}, position: [-0.55, 1.5]}\n"
         "  - {name: b4, shape: {box: [1, 1]}, position: [0.55, 1.5]}\n"
         "  - {name: top, shape: {box: [1, 1]}, position: [0, 2.5]}\n" +
         (ball ? "  - {name: ball, shape: {circle: 0.3}, position: [0.1, 12]}\n" : "") + extra;
}
constexpr int kTop = 6, kBall = 7, kPileBodies = 6;

std::vector<sim::core::BodyState> states(const sim::world::World& w) {
  std::vector<sim::core::BodyState> s;
  for (const sim::core::Body& b : w.bodies) s.push_back(b.state());
  return s;
}

bool pileAsleep(const sim::world::World& w) {
  for (int i = 1; i <= kPileBodies; ++i)
    if (!w.asleep(i)) return false;
  return true;
}

}  // namespace

TEST_CASE("sleep: a settled pile falls asleep and stays exactly still; a ball dropped on it wakes it") {
  for (const char* method : {"soft_step", "sequential"}) {
    CAPTURE(std::string(method));
    sim::world::World w = build(pile(method));
    w.advanceTo(1.0);
    // the pile at rest for kTimeToSleep sleeps, the falling ball does not; the floor never joins
    REQUIRE(pileAsleep(w));
    CHECK(!w.asleep(0));
    CHECK(!w.asleep(kBall));
    CHECK(w.sleepingBodies() == kPileBodies);
    const std::vector<sim::core::BodyState> still = states(w);
    for (int i = 1; i <= kPileBodies; ++i) CHECK(still[i].v == sim::core::Vec2::Zero());
    // no pair of the sleeping pile is solved: the contacts the solver holds are none (the ball is
    // still far above)
    CHECK(w.contacts.empty());
    w.advanceTo(1.2);
    for (int i = 1; i <= kPileBodies; ++i) {
      CAPTURE(i);
      CHECK(w.bodies[i].x == still[i].x);  // exactly: not integrated at all
      CHECK(w.bodies[i].angle == still[i].angle);
      CHECK(w.bodies[i].v == sim::core::Vec2::Zero());
    }
    // the ball lands on the top box: the pile wakes, the top box is pushed, and the bottom row
    // carries the pile again (its contacts with the floor are solved)
    const size_t impactsBefore = w.impacts.size();
    double floorImpulse = 0.0;
    while (w.time < 1.6) {
      w.advanceTo(w.time + w.def().dt);
      for (const sim::world::Contact& c : w.contacts)
        if (c.a == 0)
          for (int k = 0; k < c.manifold.count; ++k) floorImpulse += c.state[k].normalImpulse;
    }
    CHECK(w.sleepingBodies() == 0);
    CHECK(w.bodies[kTop].x != still[kTop].x);
    bool ballHitTop = false;
    for (size_t k = impactsBefore; k < w.impacts.size(); ++k)
      ballHitTop = ballHitTop || (w.impacts[k].a == kTop && w.impacts[k].b == kBall);
    CHECK(ballHitTop);
    CHECK(floorImpulse > 0.0);
  }
}

TEST_CASE("sleep: an impulse event or a force switching on wakes the island it strikes") {
  SUBCASE("an event on the bottom row") {
    sim::world::World w = build(pile("soft_step", "events:\n  - {time: 2.0, body: b2, impulse: [3, 0]}\n", false));
    w.advanceTo(1.98);
    REQUIRE(pileAsleep(w));
    const sim::core::Vec2 before = w.bodies[3].x;
    w.advanceTo(2.0);
    CHECK(w.sleepingBodies() == 0);
    CHECK(w.bodies[3].v.x() > 0.0);
    w.advanceTo(2.1);
    CHECK(w.bodies[3].x.x() > before.x());
  }
  SUBCASE("a force on from t = 2") {
    sim::world::World w =
        build(pile("sequential", "forces:\n  - {type: force, body: top, point: [0, 0], force: [0, 100], from: 2.0}\n", false));
    w.advanceTo(1.98);
    REQUIRE(pileAsleep(w));
    const double y = w.bodies[kTop].x.y();
    w.advanceTo(2.2);
    CHECK(!w.asleep(kTop));
    CHECK(w.bodies[kTop].x.y() > y + 0.01);
  }
}

TEST_CASE("sleep: until an island falls asleep the run is bit for bit the run without sleep") {
  for (const char* method : {"soft_step", "sequential"}) {
    CAPTURE(std::string(method));
    sim::world::World on = build(pile(method));
    sim::scene::SceneDef def = sim::yaml::loadSceneText(pile(method), "inline.yaml");
    def.sleep = false;
    sim::world::World off = sim::scene::buildWorld(def);
    on.advanceTo(0.4);
    off.advanceTo(0.4);
    REQUIRE(on.sleepingBodies() == 0);
    CHECK(sim::world::stateHash(on) == sim::world::stateHash(off));
  }
}

TEST_CASE("sleep: written false it is the default, and nothing sleeps however long the pile rests") {
  // (world_test.cpp's pinned hashes, untouched, hold with the key absent)
  const std::string on = pile("sequential"), key = "sleep: true";
  std::string off = on, absent = on;
  off.replace(off.find(key), key.size(), "sleep: false");
  absent.replace(absent.find(", " + key), key.size() + 2, "");
  REQUIRE(absent.find("sleep") == std::string::npos);
  sim::world::World wOff = build(off), wAbsent = build(absent);
  CHECK_FALSE(wOff.def().sleep);
  wOff.advanceTo(1.2);
  wAbsent.advanceTo(1.2);
  CHECK(wOff.sleepingBodies() == 0);
  CHECK(wOff.bodies[kTop].v != sim::core::Vec2::Zero());  // the creep that sleep would stop
  CHECK(sim::world::stateHash(wOff) == sim::world::stateHash(wAbsent));
}

TEST_CASE("sleep: refused where the method has no islands to put to sleep") {
  CHECK_THROWS_WITH_AS(build(pile("event")), doctest::Contains("use 'collisions: sequential'"), std::exception);
}

// soft_step's threads (worker_pool.h) beside sleeping: the sleeping islands' contacts are left out
// of the sets alike whatever the count, so the run is the same to the bit with 1, 2 and 3 threads
// while the pile settles, sleeps, is woken by the ball and settles again
TEST_CASE("sleep: soft_step with 2 or 3 threads gives the state hash of 1 thread, asleep and woken") {
  // a second pile far off that the ball never reaches: it sleeps through the wake of the first
  const std::string yaml = pile("soft_step",
                                "  - {name: c0, shape: {box: [1, 1]}, position: [20, 0.5]}\n"
                                "  - {name: c1, shape: {box: [1, 1]}, position: [21.1, 0.5]}\n"
                                "  - {name: c2, shape: {box: [1, 1]}, position: [20.55, 1.5]}\n");
  for (double t : {1.0, 1.6, 4.0}) {
    CAPTURE(t);
    sim::world::World one = build(yaml);
    one = fixtures::redefined(one, [&](auto& d) { d.threads = 1; });
    one.advanceTo(t);
    // asleep at 1.0 (both piles), the first pile woken at 1.6 and the far one still asleep
    if (t == 1.0) CHECK(one.sleepingBodies() == kPileBodies + 3);
    if (t == 1.6) CHECK(one.sleepingBodies() == 3);
    for (int threads : {2, 3}) {
      CAPTURE(threads);
      sim::world::World many = build(yaml);
      many = fixtures::redefined(many, [&](auto& d) {
        d.threads = threads;
        d.contactsPerThread = 1;  // every thread at work on this small pile
      });
      many.advanceTo(t);
      CHECK(many.sleepingBodies() == one.sleepingBodies());
      CHECK(sim::world::stateHash(many) == sim::world::stateHash(one));
    }
  }
}

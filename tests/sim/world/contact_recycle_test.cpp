// soft_step's contact recycling (contact_recycle.cpp, World::collectContacts): a resting pile keeps
// its manifolds and holds as it does without; a pair that moves is collided again; the state is the
// same on any number of threads.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/scene/scene_build.h"
#include "sim/world/contact_recycle.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"
#include "support/redefined.h"

namespace {

sim::world::World build(const std::string& yaml) { return sim::scene::buildWorld(sim::yaml::loadSceneText(yaml, "inline.yaml")); }

// a touching pyramid of `base` unit boxes on a half-plane, soft_step at 1/60 s
std::string pyramid(int base, const std::string& sim, const std::string& extra = "") {
  std::string s =
      "world: {gravity: [0, -10], friction: 0.6}\n"
      "sim: {collisions: soft_step, dt: 0.016666666666666667" +
      sim +
      "}\n"
      "bodies:\n"
      "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
  for (int r = 0; r < base; ++r)
    for (int j = 0; j < base - r; ++j)
      s += "  - {name: b" + std::to_string(r) + "_" + std::to_string(j) + ", shape: {box: [1, 1]}, position: [" +
           std::to_string(0.5625 * r + 1.125 * j) + ", " + std::to_string(0.5 + r) + "]}\n";
  return s + extra;
}

// the deepest overlap of any pair where the bodies are now (a fresh collision of every pair)
double deepest(const sim::world::World& w) {
  double d = 0.0;
  for (const sim::world::Contact& c : w.findContacts(0.005))
    for (int k = 0; k < c.manifold.count; ++k) d = std::min(d, c.manifold.points[k].separation);
  return -d;
}

}  // namespace

// recycledManifold's bound (contact_recycle.h): B's shift in A's frame plus the reach of its turn
// (extent × sin turn) against the distance, whichever of the two makes up most of it
TEST_CASE("a manifold is kept while B's shift plus the reach of its turn stays under the distance, and only then") {
  using sim::core::Pose;
  using sim::core::Rot;
  using sim::core::Vec2;
  sim::collision::Manifold m;
  m.count = 1;
  m.normal = Vec2(0.0, 1.0);
  m.points[0].point = Vec2(0.2, 0.5);
  m.points[0].separation = -0.01;
  const Pose a{Vec2(0.0, 0.0), Rot::fromAngle(0.0)}, b{Vec2(0.1, 1.0), Rot::fromAngle(0.0)};
  const sim::world::RecycleEntry entry = sim::world::recycleEntry(7, a, b, m);
  const double d = 0.05, extent = 0.8;
  // B shifted along x (A stays) and turned, as fractions of d
  const auto kept = [&](double shift, double reach) {
    sim::collision::Manifold out;
    const Pose moved{b.x + Vec2(shift * d, 0.0), Rot::fromAngle(std::asin(reach * d / extent))};
    return sim::world::recycledManifold(entry, a, moved, extent, d, out);
  };
  CHECK(kept(0.0, 0.0));
  CHECK(kept(0.99, 0.0));
  CHECK_FALSE(kept(1.01, 0.0));
  CHECK(kept(0.3, 0.39));  // well inside both halves
  CHECK(kept(0.5, 0.45));  // 0.95 d, most of it the turn's
  CHECK_FALSE(kept(0.5, 0.55));
  CHECK(kept(0.7, 0.2));  // 0.9 d, most of it the shift
  CHECK_FALSE(kept(0.7, 0.35));
  CHECK_FALSE(kept(0.0, 1.02));
  // at distances a scene may give whose square overflows or falls among the subnormals, the verdict
  // is the square root's: a pair past the bound is collided again
  const Pose origin{Vec2(0.0, 0.0), Rot::fromAngle(0.0)};
  const sim::world::RecycleEntry still = sim::world::recycleEntry(8, origin, origin, m);
  const auto keptAt = [&](double distance, double shift, double reach) {
    sim::collision::Manifold out;
    const Pose moved{Vec2(shift * distance, 0.0), Rot::fromAngle(std::asin(reach * distance / extent))};
    return sim::world::recycledManifold(still, origin, moved, extent, distance, out);
  };
  CHECK_FALSE(keptAt(1e155, 1.01, 0.0));
  CHECK_FALSE(keptAt(3.5e-162, 0.635, 0.4));
  CHECK(keptAt(1e-3, 0.3, 0.3));
}

TEST_CASE("a resting pyramid with recycling keeps its manifolds and holds within the measured error of one without") {
  sim::world::World fresh = build(pyramid(10, ""));
  sim::world::World kept = build(pyramid(10, ", recycle: true"));
  fresh.advanceTo(5.0);
  kept.advanceTo(5.0);
  // every touching pair of the last step kept its manifold
  CHECK(kept.recycledContacts() == static_cast<long>(kept.contacts.size()));
  CHECK(fresh.recycledContacts() == 0);
  // the top box where it is without recycling, to a millimetre (measured: 0.1 mm on this pile; the
  // 5,050-box pyramid's top 0.7405 m against 0.7410, sim/README.md), no faster, no deeper
  const sim::core::Body &topFresh = fresh.bodies.back(), &topKept = kept.bodies.back();
  CHECK((topKept.x - topFresh.x).norm() < 1e-3);
  CHECK(topKept.v.norm() < 1e-3);
  CHECK(deepest(kept) < deepest(fresh) + 1e-3);
}

TEST_CASE("a pile struck by a ball collides again the pairs the ball moves: no stale manifold on a moving pair") {
  const std::string ball = "  - {name: ball, shape: {circle: 0.3}, density: 20, position: [-3, 0.5], velocity: [12, 0]}\n";
  sim::world::World w = build(pyramid(4, ", recycle: true", ball));
  sim::world::World fresh = build(pyramid(4, "", ball));
  // the ball reaches the bottom row's first box at about 0.19 s; from then on, every pair that
  // moved relative to each other by twice the recycling distance over the step before has a manifold
  // made where this step began
  int checked = 0;
  sim::world::World previous = w;  // where the step before began
  for (int step = 1; step <= 60; ++step) {
    const double t = step / 60.0;
    const sim::world::World start = w;  // the poses this step's contacts are found at
    w.advanceTo(t);
    fresh.advanceTo(t);
    for (const sim::world::Contact& c : w.contacts) {
      // B's pose in A's frame at the two starts: how far B's points moved relative to A
      const auto relative = [&](const sim::world::World& at) {
        const sim::core::Body &a = at.bodies[c.a], &b = at.bodies[c.b];
        return std::pair{a.pose().toBody(b.x), b.angle - a.angle};
      };
      const auto [x0, angle0] = relative(previous);
      const auto [x1, angle1] = relative(start);
      if ((x1 - x0).norm() + 0.71 * std::abs(angle1 - angle0) < 2.0 * sim::core::settings::kRecycleDistance) continue;
      // a manifold made there: a fresh collision's of the pair, to the bit
      const sim::core::Body &a = start.bodies[c.a], &b = start.bodies[c.b];
      const sim::collision::Manifold m = sim::collision::collide(a.shape, a.pose(), b.shape, b.pose(), 1.0);
      CAPTURE(t);
      CHECK(m.normal == c.manifold.normal);
      CHECK(m.points[0].point == c.manifold.points[0].point);
      ++checked;
    }
    previous = start;
  }
  CHECK(checked > 0);
  // the struck pile scatters as it does without recycling, to the measured difference (up to 0.095 m
  // a second after a strike at 12 m/s: the manifolds a resting pair keeps differ from fresh ones by
  // up to the recycling distance, and the scattering magnifies it), and nothing sinks into the floor
  for (size_t i = 1; i < w.bodies.size(); ++i) {
    CHECK((w.bodies[i].x - fresh.bodies[i].x).norm() < 0.2);
    CHECK(w.bodies[i].x.y() > 0.25);
  }
}

TEST_CASE("recycling gives the same state on one thread and on two") {
  sim::world::World one = build(pyramid(12, ", recycle: true"));
  // (every thread at work on this small pile)
  sim::world::World two =
      fixtures::redefined(build(pyramid(12, ", recycle: true, threads: 2")), [](auto& d) { d.contactsPerThread = 1; });
  one.advanceTo(2.0);
  two.advanceTo(2.0);
  CHECK(sim::world::stateHash(one) == sim::world::stateHash(two));
  CHECK(one.recycledContacts() == two.recycledContacts());
}

// one thread writes a recycled manifold into its own contact (ContactFinder's collideInOrder), two
// collide into a list and then write; where a struck pile's pairs move, come and go, both give the
// same state, step after step
TEST_CASE("recycling into the contacts themselves gives the state of recycling into a list, on a struck pile") {
  const std::string ball = "  - {name: ball, shape: {circle: 0.3}, density: 20, position: [-3, 0.5], velocity: [12, 0]}\n";
  sim::world::World one = build(pyramid(8, ", recycle: true", ball));
  sim::world::World two =
      fixtures::redefined(build(pyramid(8, ", recycle: true, threads: 2", ball)), [](auto& d) { d.contactsPerThread = 1; });
  long recycledOnSome = 0, collidedOnSome = 0;
  for (int step = 1; step <= 90; ++step) {
    one.advanceTo(step / 60.0);
    two.advanceTo(step / 60.0);
    CAPTURE(step);
    REQUIRE(sim::world::stateHash(one) == sim::world::stateHash(two));
    CHECK(one.recycledContacts() == two.recycledContacts());
    const long recycled = one.recycledContacts(), all = static_cast<long>(one.contacts.size());
    recycledOnSome += recycled > 0 && recycled < all;
    collidedOnSome += recycled < all;
  }
  // (steps where some pairs kept their manifolds and others were collided again: the writes into
  // the contacts stopped part way through the list)
  CHECK(recycledOnSome > 10);
  CHECK(collidedOnSome > 10);
}

TEST_CASE("a look at the contacts does not change what the solver's last step recycled") {
  sim::world::World kept = build(pyramid(6, ", recycle: true"));
  kept.advanceTo(1.0);
  const long recycled = kept.recycledContacts();
  CHECK(recycled > 0);
  (void)deepest(kept);  // findContacts(margin): a fresh collision of every pair
  CHECK(kept.recycledContacts() == recycled);
}

#include "sim/world/contact_finder.h"

#include <doctest/doctest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "sim/scene/scene_build.h"
#include "sim/world/worker_pool.h"
#include "sim/yaml/scene_yaml.h"

namespace {
using sim::world::Contact;
using sim::world::ContactFinder;
using sim::world::ContactQuery;

// a unit box resting on a floor (its corners 1 mm into it), a second box whose side touches the
// first's, and a ball 0.5 m clear of the box: three touching pairs, one pair apart
const char* kScene = R"(
sim: {dt: 0.01}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}, static: true}
  - {name: box, shape: {box: [1, 1]}, position: [0, 0.499]}
  - {name: other, shape: {box: [1, 1]}, position: [1.0, 0.499]}
  - {name: ball, shape: {circle: 0.25}, position: [0, 1.749]}
)";

std::vector<sim::core::Body> bodies() { return sim::scene::buildWorld(sim::yaml::loadSceneText(kScene, "inline.yaml")).bodies; }

// the manifolds of two lists, equal to the bit, with their pairs
void checkSame(const std::vector<Contact>& a, const std::vector<Contact>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(pairKey(a[i]) == pairKey(b[i]));
    REQUIRE(a[i].manifold.count == b[i].manifold.count);
    for (int k = 0; k < a[i].manifold.count; ++k) {
      CHECK(a[i].manifold.points[k].point == b[i].manifold.points[k].point);
      CHECK(a[i].manifold.points[k].separation == b[i].manifold.points[k].separation);
    }
  }
}

}  // namespace

TEST_CASE("the finder gives the manifolds of the pairs within the margin, sorted by pair, with combined coefficients") {
  const std::vector<sim::core::Body> b = bodies();
  const sim::world::Sleep awake;
  const std::vector<Contact> none;
  ContactFinder finder;
  std::vector<Contact> found;
  (void)finder.collect(ContactQuery{b, awake, none, 0.01}, found);
  // floor–box and floor–other with two corners each, 1 mm deep; box–other side by side; not the ball
  REQUIRE(found.size() == 3);
  CHECK(pairKey(found[0]) == std::make_tuple(0, 0, 1, 0));
  CHECK(pairKey(found[1]) == std::make_tuple(0, 0, 2, 0));
  CHECK(pairKey(found[2]) == std::make_tuple(1, 0, 2, 0));
  for (int i : {0, 1}) {
    REQUIRE(found[i].manifold.count == 2);
    for (int k = 0; k < 2; ++k) CHECK(found[i].manifold.points[k].separation == doctest::Approx(-0.001).epsilon(1e-9));
    CHECK(found[i].friction == doctest::Approx(std::sqrt(b[0].friction * b[1].friction)).epsilon(1e-15));
  }
  // a margin that reaches the ball (its gap to the box 0.5 m) adds its pair
  (void)finder.collect(ContactQuery{b, awake, none, 0.6}, found);
  CHECK(found.size() == 4);
}

TEST_CASE("the finder's scratch changes nothing: a fresh finder, a reused one and two threads find the same") {
  const std::vector<sim::core::Body> b = bodies();
  const sim::world::Sleep awake;
  const std::vector<Contact> none;
  ContactFinder fresh, reused;
  std::vector<Contact> a, c, d;
  (void)reused.collect(ContactQuery{b, awake, none, 0.6}, c);  // other scratch first
  (void)fresh.collect(ContactQuery{b, awake, none, 0.01}, a);
  (void)reused.collect(ContactQuery{b, awake, none, 0.01}, c);
  checkSame(a, c);
  sim::world::WorkerPool two(2);
  ContactFinder threaded;
  (void)threaded.collect(ContactQuery{b, awake, none, 0.01}, d, &two);
  checkSame(a, d);
}

TEST_CASE("warm start: each point starts from last step's impulse of the same pair and features; a look does not") {
  const std::vector<sim::core::Body> b = bodies();
  const sim::world::Sleep awake;
  const std::vector<Contact> none;
  ContactFinder finder;
  std::vector<Contact> last;
  (void)finder.collect(ContactQuery{b, awake, none, 0.01}, last);
  REQUIRE(last.size() == 3);
  last[1].state[0].normalImpulse = 0.25, last[1].state[1].tangentImpulse = -0.5;
  std::vector<Contact> found;
  ContactQuery warm{b, awake, last, 0.01};
  warm.warmStart = true;
  (void)finder.collect(warm, found);
  REQUIRE(found.size() == 3);
  CHECK(found[1].state[0].normalImpulse == 0.25);
  CHECK(found[1].state[1].tangentImpulse == -0.5);
  CHECK(found[0].state[0].normalImpulse == 0.0);
  // without the warm start every point starts from nothing
  (void)finder.collect(ContactQuery{b, awake, last, 0.01}, found);
  CHECK(found[1].state[0].normalImpulse == 0.0);
  // given last step's list to write over, the same pairs are written over their own: kept, and the
  // lists' storage swapped (found now holds the contacts, last the old storage)
  const Contact* storage = last.data();
  CHECK(finder.collect(warm, found, nullptr, &last));
  CHECK(found.data() == storage);
  CHECK(found[1].state[0].normalImpulse == 0.25);
  // a list whose pairs are not these (one fewer) is not written over: the contacts go to `other`,
  // still warm started from it
  std::vector<Contact> fewer(found.begin(), found.begin() + 2), other;
  ContactQuery fromFewer{b, awake, fewer, 0.01};
  fromFewer.warmStart = true;
  CHECK_FALSE(finder.collect(fromFewer, other, nullptr, &fewer));
  REQUIRE(other.size() == 3);
  CHECK(fewer.size() == 2);
  CHECK(other[1].state[0].normalImpulse == 0.25);
}

TEST_CASE("recycling: a pair that did not move keeps its manifold; one moved past the distance is collided again") {
  std::vector<sim::core::Body> b = bodies();
  const sim::world::Sleep awake;
  std::vector<Contact> last;
  ContactFinder finder;
  ContactQuery query{b, awake, last, 0.01};
  query.warmStart = true;
  query.recycleDistance = 0.005;
  std::vector<Contact> found;
  (void)finder.collect(query, found);
  CHECK(finder.recycled() == 0);
  last = found;
  (void)finder.collect(query, found);
  CHECK(finder.recycled() == 3);
  // the second box lifted 1 cm, past the 5 mm: its pairs with the floor and with the box are new
  last = found;
  b[2].x.y() += 0.01;
  (void)finder.collect(query, found);
  CHECK(finder.recycled() == 1);
  // with recycling off, nothing is kept
  query.recycleDistance = 0.0;
  (void)finder.collect(query, found);
  CHECK(finder.recycled() == 0);
}

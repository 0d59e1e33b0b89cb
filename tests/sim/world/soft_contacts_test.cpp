// soft_step's contact passes in SIMD lanes and lane by lane (soft_contacts.h): the same colours
// and blocks in the same order, so the two paths give the same state to the bit on the pyramids
// and on a pile of tumbling mixed shapes.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "sim/core/simd_support.h"
#include "sim/world/soft_contacts.h"
#include "support/scene_text.h"
#include "support/redefined.h"

namespace {

using scene_text::vec;

// Box2D's pyramid on a half-plane floor, as a scene file writes it
const char* kSettings =
    "world: {gravity: [0, -10], friction: 0.6, restitution: 0}\n"
    "sim: {collisions: soft_step, dt: 0.016666666666666667}\n"
    "bodies:\n"
    "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";

std::string pyramid(int base, bool dropped) {
  std::string yaml = kSettings;
  for (int r = 0; r < base; ++r)
    for (int j = 0; j < base - r; ++j)
      yaml += "  - {name: b" + std::to_string(r) + "_" + std::to_string(j) +
              ", shape: {box: [1, 1]}, position: " + vec(-7.0 + 0.5625 * r + 1.125 * j, dropped ? 0.75 + 1.25 * r : 0.5 + r) +
              "}\n";
  return yaml;
}

// random convex bodies dropped in a box, turning, with restitution: speculative points, the
// overflow-free colours of a jumbled pile
std::string pile() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string yaml =
      "world: {gravity: [0, -10], friction: 0.4, restitution: 0.3}\n"
      "sim: {collisions: soft_step, dt: 0.01}\n"
      "bodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: left, shape: {plane: {point: [-3, 0], normal: [1, 0]}}}\n"
      "  - {name: right, shape: {plane: {point: [3, 0], normal: [-1, 0]}}}\n";
  for (int i = 0; i < 60; ++i) {
    const std::string shape = scene_text::randomShape(rng);
    const double x = -2.5 + 5.0 * u(rng);
    const double w = -3.0 + 6.0 * u(rng);
    yaml += "  - {name: s" + std::to_string(i) + ", shape: " + shape + ", position: " + vec(x, 0.8 + 0.7 * i) +
            ", angular_velocity: " + scene_text::num(w) + "}\n";
  }
  return yaml;
}

// width: the most SIMD lanes the passes may use (8: AVX-512 where there, 4: AVX2, 1: scalar)
unsigned long long run(const std::string& yaml, int width, double seconds, int threads = 1,
                       sim::world::Precision precision = sim::world::Precision::Double) {
  sim::world::World w = scene_text::build(yaml);
  w = fixtures::redefined(w, [&](auto& d) {
    d.simdWidth = width;
    d.threads = threads;
    d.contactsPerThread = 1;  // every thread at work on these small piles
    d.precision = precision;
  });
  w.advanceTo(seconds);
  return sim::world::stateHash(w);
}

// the scenes the threads and the floats are tried on
std::vector<std::pair<const char*, std::string>> threadedScenes() {
  return {{"pyramid 20 dropped", pyramid(20, true)}, {"pyramid 40 touching", pyramid(40, false)}, {"pile", pile()}};
}

}  // namespace

TEST_CASE("soft_step: the AVX-512, AVX2 and scalar contact passes give the same state hash (pyramids, a tumbling pile)") {
  MESSAGE("on this processor: AVX-512 path " << (sim::core::avx512Available() ? "yes" : "no (runs AVX2 or scalar)")
                                             << ", AVX2 path " << (sim::core::avx2Available() ? "yes" : "no (runs scalar)"));
  const std::pair<const char*, std::string> scenes[] = {
      {"pyramid 20 touching", pyramid(20, false)},
      {"pyramid 20 dropped", pyramid(20, true)},
      {"pyramid 40 touching", pyramid(40, false)},
      {"pile", pile()},
  };
  // no structured binding: clang 14 cannot capture one in CAPTURE (make sanitize builds with it)
  for (const auto& scene : scenes) {
    CAPTURE(std::string(scene.first));
    const unsigned long long scalar = run(scene.second, 1, 3.0);
    CHECK(run(scene.second, 4, 3.0) == scalar);
    CHECK(run(scene.second, 8, 3.0) == scalar);
  }
}

// in floats (sim: precision: float) a block is sixteen lanes, one AVX-512 register or two halves in
// AVX2's: the same state as the scalar floats, to the bit; and not the doubles' state (the test
// would pass if float were ignored)
TEST_CASE("soft_step in floats: the AVX-512, AVX2 and scalar contact passes give the same state hash, 1 or 2 threads") {
  const auto kFloat = sim::world::Precision::Float;
  for (const auto& scene : threadedScenes()) {
    CAPTURE(std::string(scene.first));
    const unsigned long long scalar = run(scene.second, 1, 2.0, 1, kFloat);
    CHECK(run(scene.second, 8, 2.0, 1, kFloat) == scalar);
    CHECK(run(scene.second, 4, 2.0, 1, kFloat) == scalar);
    CHECK(run(scene.second, 8, 2.0, 2, kFloat) == scalar);
    CHECK(run(scene.second, 1, 2.0, 2, kFloat) == scalar);
    CHECK(run(scene.second, 8, 2.0) != scalar);
  }
}

// the sets split between threads (worker_pool.h): each set's contacts touch disjoint bodies, so
// who solves which changes nothing, to the bit, with the wide or the scalar passes
TEST_CASE("soft_step: 1, 2 and 3 threads give the same state hash (pyramids, a tumbling pile)") {
  for (const auto& scene : threadedScenes()) {
    CAPTURE(std::string(scene.first));
    const unsigned long long one = run(scene.second, 8, 2.0, 1);
    CHECK(run(scene.second, 8, 2.0, 2) == one);
    CHECK(run(scene.second, 8, 2.0, 3) == one);
    CHECK(run(scene.second, 4, 2.0, 2) == one);
    CHECK(run(scene.second, 1, 2.0, 2) == run(scene.second, 1, 2.0, 1));
  }
}

TEST_CASE("soft_step: sim: threads reaches the world, and a copy of a threaded world steps on its own") {
  sim::world::World w = scene_text::build(pyramid(10, true) + "");
  w = fixtures::redefined(w, [&](auto& d) {
    d.threads = 2;
    d.contactsPerThread = 1;
  });
  w.advanceTo(0.5);
  sim::world::World copy = w;  // the copy makes its own threads
  copy.advanceTo(1.0);
  w.advanceTo(1.0);
  CHECK(sim::world::stateHash(copy) == sim::world::stateHash(w));
  std::string yaml = pyramid(3, false);
  yaml.replace(yaml.find("dt: 0.016666666666666667}"), 25, "dt: 0.016666666666666667, threads: 2}");
  CHECK(scene_text::build(yaml).def().threads == 2);
}

// Scenes written as inline YAML for the collision tests: numbers in round-trip form, random convex
// bodies, and Newton's cradle; shared by the tests of the three collision methods.
#pragma once

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"
#include "sim/yaml/scene_yaml.h"

namespace scene_text {

// a number that reads back as the same double
inline std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
inline std::string vec(double x, double y) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", x, y);
  return buf;
}

inline sim::world::World build(const std::string& yaml) {
  return sim::scene::buildWorld(sim::yaml::loadSceneText(yaml, "inline.yaml"));
}

// a random convex shape as YAML: a circle, a box, or a polygon with 3 to 7 vertices on a circle
inline std::string randomShape(std::mt19937_64& rng) {
  // every draw in its own statement, so the scenes do not depend on the order a compiler evaluates
  // function arguments in
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int kind = static_cast<int>(u(rng) * 3.0);
  if (kind == 0) {
    const double r = 0.2 + 0.4 * u(rng);
    return "{circle: " + num(r) + "}";
  }
  if (kind == 1) {
    const double w = 0.2 + u(rng);
    const double h = 0.2 + u(rng);
    return "{box: " + vec(w, h) + "}";
  }
  const int n = 3 + static_cast<int>(u(rng) * 5.0);
  const double radius = 0.3 + 0.4 * u(rng), step = 2.0 * 3.14159265358979 / n;
  std::string s = "{polygon: [";
  for (int k = 0; k < n; ++k) {
    const double angle = step * (k + 0.3 * (u(rng) - 0.5));
    s += (k ? ", " : "") + vec(radius * std::cos(angle), radius * std::sin(angle));
  }
  return s + "]}";
}

// a body of a random shape and density at x = `x`, y within ±0.3, any angle, moving along x at a
// speed in `vx` ± spread, a little along y, spinning up to 3 rad/s either way
inline std::string randomBody(std::mt19937_64& rng, const char* name, double x, double vx, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  const std::string shape = randomShape(rng);
  const double density = 0.5 + 2.5 * unit(rng);
  const double y = 0.3 * u(rng);
  const double angle = 3.0 * u(rng);
  const double speed = vx + spread * u(rng);
  const double vy = 0.2 * u(rng);
  const double omega = 3.0 * u(rng);
  return std::string("  - {name: ") + name + ", shape: " + shape + ", density: " + num(density) + ", position: " + vec(x, y) +
         ", angle: " + num(angle) + ", velocity: " + vec(speed, vy) + ", angular_velocity: " + num(omega) + "}\n";
}

// Newton's cradle seen from above: five equal balls, c_r = 1, no gravity, four touching, one striking
inline constexpr const char* kCradle = R"(
world: {restitution: 1}
bodies:
  - {name: b1, shape: {circle: 0.5}, mass: 1, position: [-2, 0], velocity: [1, 0]}
  - {name: b2, shape: {circle: 0.5}, mass: 1, position: [1, 0]}
  - {name: b3, shape: {circle: 0.5}, mass: 1, position: [2, 0]}
  - {name: b4, shape: {circle: 0.5}, mass: 1, position: [3, 0]}
  - {name: b5, shape: {circle: 0.5}, mass: 1, position: [4, 0]}
)";

// the cradle run for 3 s by one method: momentum and kinetic energy before and after
struct CradleRun {
  sim::world::World world;
  sim::core::Vec2 p0;
  double e0, e1;
  std::string speeds;  // the balls' final x velocities
};
inline CradleRun runCradle(sim::core::CollisionMethod method) {
  sim::scene::SceneDef def = sim::yaml::loadSceneText(kCradle, "inline.yaml");
  def.collisions = method;
  CradleRun r{sim::scene::buildWorld(def), {}, 0.0, 0.0, {}};
  r.p0 = sim::world::linearMomentum(r.world);
  r.e0 = sim::world::energy(r.world).kinetic;
  r.world.advanceTo(3.0);
  r.e1 = sim::world::energy(r.world).kinetic;
  for (const sim::core::Body& b : r.world.bodies) r.speeds.append(" ").append(num(b.v.x()));
  return r;
}

}  // namespace scene_text

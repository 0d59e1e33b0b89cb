// The 3D scene reader: `dimensions: 3` scenes give the documented values and defaults, variants
// merge as in 2D, and every bad input is a SceneError at its FILE:LINE:COL naming the fault (a 2D
// key saying why 3D has none).
#include "sim/yaml3d/scene_yaml.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "sim/scene3d/scene_build.h"
#include "support/scene_error_check.h"

using namespace sim::scene3d;
using sim::core::kWorldAnchor;
using namespace sim::world3d;

namespace {

const scene_errors::InlineSceneErrors expectSceneError{sim::yaml3d::loadSceneText};

// a 3D scene with one body `a` (a unit cube) on lines 1-4; tests append lines 5, 6, ...
const std::string kOneBody =
    "dimensions: 3\n"
    "bodies:\n"
    "  - name: a\n"
    "    shape: {box: [1, 1, 1]}\n";

}  // namespace

TEST_CASE("a 3D scene: values, defaults and the mass properties of each way of giving them") {
  const SceneDef s = sim::yaml3d::loadSceneText(R"(
dimensions: 3
duration: 2
world: {gravity: [0, 0, -9.81]}
sim: {integrator: rk4, dt: 0.01, normalize: false}
bodies:
  - {name: brick, shape: {box: [0.2, 0.4, 0.6]}, density: 500, position: [1, 2, 3], orientation: [0, 1, 0, 0],
     velocity: [1, 0, 0], angular_velocity: [0, 0, 2]}
  - {name: ball, shape: {sphere: 0.5}, mass: 2, orientation: {axis: [0, 0, 1], angle: 1.5707963267948966}}
  - {name: egg, shape: {ellipsoid: [0.1, 0.2, 0.3]}, mass: 1, inertia: [1, 2, 2.5]}
  - {name: slab, shape: {box: [1, 1, 1]}, mass: 1, inertia: [[2, 0.1, 0], [0.1, 2, 0], [0, 0, 3]]}
forces:
  - {type: spring, body: brick, point: [0.1, 0, 0], anchor: [0, 0, 5], stiffness: 10, rest_length: 1}
  - {type: force, body: ball, point: [0, 0, 0.5], frame: body, force: [1, 0, 0], from: 0.5, until: 1}
  - {type: drag, body: egg, linear: 0.1, angular: 0.2}
events:
  - {time: 1, body: slab, impulse: [0, 1, 0], point: [0.5, 0, 0]}
expect:
  - {time: 2, body: brick, orientation: [0, 1, 0, 0], flip_period: 3, tolerance: 1e-6}
)",
                                                scene_errors::kInlineFile);
  CHECK(s.name == "inline");
  CHECK(s.duration == 2.0);
  CHECK(s.gravity == Vec3(0, 0, -9.81));
  CHECK(s.integrator == Integrator::Rk4);
  CHECK(s.dt == 0.01);
  CHECK_FALSE(s.normalize);
  REQUIRE(s.bodies.size() == 4);
  const World w = buildWorld(s);
  // density: ρ a b c, and the box's (b² + c²)/12 per kg about x
  CHECK(w.bodies[0].mass == doctest::Approx(500 * 0.048));
  CHECK(w.bodies[0].inertiaBody(0, 0) == doctest::Approx(500 * 0.048 * (0.16 + 0.36) / 12));
  CHECK(w.bodies[0].q.coeffs() == Quat(0, 1, 0, 0).coeffs());
  CHECK(w.bodies[0].omega == Vec3(0, 0, 2));
  // mass alone: spread uniformly, 2/5 m r² for a sphere
  CHECK(w.bodies[1].inertiaBody(2, 2) == doctest::Approx(0.4 * 2 * 0.25));
  CHECK(w.bodies[1].q.w() == doctest::Approx(std::sqrt(0.5)));
  CHECK(w.bodies[1].q.z() == doctest::Approx(std::sqrt(0.5)));
  // principal moments, and a full tensor, as written
  CHECK(w.bodies[2].inertiaBody == Mat3(Vec3(1, 2, 2.5).asDiagonal()));
  CHECK(w.bodies[3].inertiaBody(0, 1) == 0.1);
  CHECK_FALSE(w.def().normalizeQuaternions);
  REQUIRE(w.def().forces.springs.size() == 1);
  CHECK(w.def().forces.springs[0].bodyB == kWorldAnchor);
  CHECK(w.def().forces.springs[0].pointB == Vec3(0, 0, 5));
  REQUIRE(w.def().forces.pointForces.size() == 1);
  CHECK(w.def().forces.pointForces[0].bodyFrame);
  CHECK(w.def().forces.pointForces[0].until == 1.0);
  CHECK(w.def().forces.drags[0].angular == 0.2);
  REQUIRE(w.def().events.size() == 1);
  CHECK(w.def().events[0].body == 3);
  REQUIRE(s.expects.size() == 1);
  CHECK(s.expects[0].flipPeriod == 3.0);
  CHECK(s.expects[0].tolerance == 1e-6);
}

TEST_CASE("3D defaults: the splitting, normalized, unit density, at rest at the origin") {
  const SceneDef s = sim::yaml3d::loadSceneText(kOneBody, scene_errors::kInlineFile);
  CHECK(s.integrator == Integrator::Splitting);
  CHECK(s.normalize);
  CHECK(s.gravity == Vec3::Zero());
  const World w = buildWorld(s);
  CHECK(w.bodies[0].mass == doctest::Approx(1.0));
  CHECK(w.bodies[0].x == Vec3::Zero());
  CHECK(w.bodies[0].q.coeffs() == Quat::Identity().coeffs());
}

TEST_CASE("a typed quaternion within round-off of unit length is normalized; one further off is refused") {
  const SceneDef s =
      sim::yaml3d::loadSceneText(kOneBody + "    orientation: [0.7071068, 0.7071068, 0, 0]\n", scene_errors::kInlineFile);
  CHECK(std::abs(s.bodies[0].orientation.norm() - 1.0) < 1e-15);
  EXPECT_SCENE_ERROR(kOneBody + "    orientation: [1, 0.1, 0, 0]\n", 5, 18, {"unit length", "1.004988"});
  EXPECT_SCENE_ERROR(kOneBody + "    orientation: [1, 0, 0]\n", 5, 18, {"[w, x, y, z]", "3 values"});
  EXPECT_SCENE_ERROR(kOneBody + "    orientation: {axis: [0, 0, 0], angle: 1}\n", 5, 18, {"non-zero"});
  EXPECT_SCENE_ERROR(kOneBody + "    orientation: {axis: [0, 0, 1], turn: 1}\n", 5, 36, {"unknown key 'turn'"});
}

TEST_CASE("variants deep-merge over a 3D scene as over a 2D one, and cannot change the dimensions") {
  const std::string text = kOneBody +
                           "    velocity: [1, 0, 0]\n"
                           "variants:\n"
                           "  fast: {bodies: [{name: a, velocity: [2, 0, 0]}], sim: {integrator: rk4}}\n"
                           "  flat: {dimensions: 2}\n";
  EXPECT_SCENE_ERROR(text, 8, 22, {"cannot change 'dimensions'"}, "fast");
  const std::string good = kOneBody +
                           "    velocity: [1, 0, 0]\n"
                           "variants:\n"
                           "  fast: {bodies: [{name: a, velocity: [2, 0, 0]}], sim: {integrator: rk4}}\n"
                           "  base: {}\n";
  const SceneDef fast = sim::yaml3d::loadSceneText(good, scene_errors::kInlineFile, "fast");
  CHECK(fast.variant == "fast");
  CHECK(fast.variantNames == std::vector<std::string>{"fast", "base"});
  CHECK(fast.bodies[0].velocity == Vec3(2, 0, 0));
  CHECK(fast.integrator == Integrator::Rk4);
  CHECK(sim::yaml3d::loadSceneText(good, scene_errors::kInlineFile, "base").bodies[0].velocity == Vec3(1, 0, 0));
}

TEST_CASE("2D keys in a 3D scene say why 3D has none; 3D keys are checked where they are written") {
  EXPECT_SCENE_ERROR(kOneBody + "sim: {collisions: soft_step}\n", 5, 19, {"2D method", "'sequential'"});
  EXPECT_SCENE_ERROR(kOneBody + "sim: {substeps: 4}\n", 5, 17, {"no soft_step"});
  EXPECT_SCENE_ERROR(kOneBody + "world: {restitution: 2}\n", 5, 22, {"within [0, 1]"});
  EXPECT_SCENE_ERROR(kOneBody + "    angle: 1\n", 5, 12, {"orientation"});
  EXPECT_SCENE_ERROR(kOneBody + "    static: true\n", 5, 13, {"no static bodies", "plane"});
  EXPECT_SCENE_ERROR("dimensions: 3\nbodies:\n  - {name: a, shape: {circle: 1}}\n", 3, 22, {"2D shape", "sphere"});
  EXPECT_SCENE_ERROR(kOneBody + "    velocity: [1, 0]\n", 5, 15, {"[x, y, z]", "2 values"});
  EXPECT_SCENE_ERROR(kOneBody + "    angular_velocty: [1, 0, 0]\n", 5, 5, {"unknown key", "'angular_velocity'"});
  EXPECT_SCENE_ERROR(kOneBody + "sim: {integrator: verlet}\n", 5, 19, {"verlet", "splitting"});
  EXPECT_SCENE_ERROR("dimensions: 3\nbodies:\n  - {name: a, shape: {box: [1, -1, 1]}}\n", 3, 22, {"positive"});
  // the moments of no solid: the triangle inequality I1 + I2 >= I3 fails, at the inertia
  EXPECT_SCENE_ERROR(kOneBody + "    mass: 1\n    inertia: [1, 1, 3]\n", 6, 14, {"triangle inequality"});
  EXPECT_SCENE_ERROR(kOneBody + "    mass: 1\n    inertia: [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]\n", 6, 14, {"symmetric"});
  EXPECT_SCENE_ERROR(kOneBody + "expect:\n  - {time: 0.5, body: b, position: [0, 0, 0]}\n", 6, 23, {"no body named 'b'", "a"});
  EXPECT_SCENE_ERROR(kOneBody + "expect:\n  - {time: 0.5, angular_velocity: [0, 0, 0]}\n", 6, 35, {"a body's"});
  EXPECT_SCENE_ERROR(kOneBody + "expect:\n  - {time: 0.5, body: a, angle: 1}\n", 6, 33, {"orientation"});
  EXPECT_SCENE_ERROR(kOneBody + "expect:\n  - {time: 2, body: a, flip_period: 1}\n", 6, 12, {"outside", "duration"});
  EXPECT_SCENE_ERROR(kOneBody + "events:\n  - {time: 0.5, body: a, impulse: [1, 0, 0], frame: space}\n", 6, 53,
                     {"'body' or 'world'"});
}

TEST_CASE("dimensions: 2 or 3, read once for every reader; the 2D reader refuses a 3D scene") {
  EXPECT_SCENE_ERROR("dimensions: 4\nbodies: [{name: a, shape: {box: [1, 1, 1]}}]\n", 1, 13, {"2", "3"});
  // the 2D reader takes `dimensions: 2` as it takes no dimensions at all, and says where a 3D scene is read
  CHECK(sim::yaml::loadSceneText("dimensions: 2\nbodies: [{name: a, shape: {circle: 1}}]\n", scene_errors::kInlineFile)
            .bodies.size() == 1);
  scene_errors::expectSceneError(
      [](const std::string& t, const std::string& f, const std::string& v) { return sim::yaml::loadSceneText(t, f, v); },
      scene_errors::kInlineFile, kOneBody, 1, 13, {"3D", "sim::yaml3d"});
  // and the 3D reader a 2D one
  EXPECT_SCENE_ERROR("bodies: [{name: a, shape: {box: [1, 1, 1]}}]\n", 1, 1, {"dimensions: 3"});
}

TEST_CASE("a 3D scene's name is one file name, and its run is bounded, as in 2D") {
  EXPECT_SCENE_ERROR("name: ../escaped\n" + kOneBody, 1, 7, {"'../escaped'", "names its output files"});
  EXPECT_SCENE_ERROR("name: \"\"\n" + kOneBody, 1, 7, {"names its output files"});
  // 1e-12 for 1e-2: 1e15 steps, refused at the dt that asks for them, naming the way to allow them
  EXPECT_SCENE_ERROR(kOneBody + "duration: 1000\nsim: {dt: 1e-12}\n", 6, 11, {"1e+15 steps", "max_steps"});
  const SceneDef allowed =
      sim::yaml3d::loadSceneText(kOneBody + "duration: 1\nsim: {dt: 1e-3, max_steps: 1000}\n", scene_errors::kInlineFile, "");
  CHECK(allowed.maxSteps == 1000.0);
  EXPECT_SCENE_ERROR(kOneBody + "duration: 1\nsim: {dt: 1e-3, max_steps: 999}\n", 6, 11, {"1000 steps", "999"});
}

TEST_CASE("planes, restitution, friction and the collision methods of a 3D scene") {
  const std::string scene =
      "dimensions: 3\n"
      "world: {gravity: [0, 0, -9.81], restitution: 0.3, friction: 0.4}\n"
      "sim: {collisions: sequential, iterations: 12, position_iterations: 2}\n"
      "bodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0, -1], normal: [0, 0, 2]}}, friction: 0.9}\n"
      "  - {name: ball, shape: {sphere: 0.5}, restitution: 0.8}\n";
  const sim::scene3d::SceneDef s = sim::yaml3d::loadSceneText(scene, scene_errors::kInlineFile);
  REQUIRE(s.planes.size() == 1);
  REQUIRE(s.bodies.size() == 1);
  CHECK(s.planes[0].name == "floor");
  CHECK(s.planes[0].point == Vec3(0, 0, -1));
  CHECK(s.planes[0].normal == Vec3(0, 0, 1));  // normalized
  CHECK(*s.planes[0].friction == 0.9);
  CHECK(*s.bodies[0].restitution == 0.8);
  CHECK(s.restitution == 0.3);
  CHECK(*s.friction == 0.4);
  CHECK(s.collisions == sim::core::CollisionMethod::Sequential);
  CHECK(s.velocityIterations == 12);
  CHECK(s.positionIterations == 2);
  // what a plane is not, and a body pair 3D does not collide
  EXPECT_SCENE_ERROR(
      "dimensions: 3\nbodies:\n  - {name: f, shape: {plane: {normal: [0, 0, 0]}}}\n  - {name: b, shape: {sphere: 1}}\n", 3, 39,
      {"normal must not be zero"});
  EXPECT_SCENE_ERROR(
      "dimensions: 3\nbodies:\n  - {name: f, shape: {plane: {normal: [0, 0, 1]}}, position: [0, 0, 1]}\n  - {name: b, shape: "
      "{sphere: 1}}\n",
      3, 62, {"a plane has no 'position'", "'point'"});
  EXPECT_SCENE_ERROR("dimensions: 3\nbodies:\n  - {name: f, shape: {plane: {normal: [0, 0, 1]}}}\n", 3, 3,
                     {"at least one body that moves"});
  EXPECT_SCENE_ERROR(
      "dimensions: 3\nbodies:\n  - {name: f, shape: {plane: {normal: [0, 0, 1]}}}\n  - {name: a, shape: {box: [1, 1, 1]}}\n"
      "  - {name: b, shape: {sphere: 1}, position: [3, 0, 0]}\n",
      5, 5, {"two spheres only", "'b' and 'a'", "collisions: none"});
  // without planes or a named method nothing collides, and boxes may share a scene as before
  CHECK(
      sim::yaml3d::loadSceneText("dimensions: 3\nbodies:\n  - {name: a, shape: {box: [1, 1, 1]}}\n  - {name: b, shape: {box: [1, "
                                 "1, 1]}}\n",
                                 scene_errors::kInlineFile)
          .bodies.size() == 2);
  // but two spheres may meet under auto without a plane, so a box beside them is refused too
  EXPECT_SCENE_ERROR(
      "dimensions: 3\nbodies:\n  - {name: a, shape: {sphere: 1}}\n  - {name: b, shape: {sphere: 1}, position: [3, 0, 0]}\n"
      "  - {name: c, shape: {box: [1, 1, 1]}, position: [6, 0, 0]}\n",
      5, 5, {"two spheres only", "'c' and 'b'"});
  // a normal far from unit length in either direction comes out unit
  for (const char* normal : {"[1e200, 0, 0]", "[1e-160, 0, 0]", "[3, 0, 4]"}) {
    CAPTURE(normal);
    const sim::scene3d::SceneDef s =
        sim::yaml3d::loadSceneText(std::string("dimensions: 3\nbodies:\n  - {name: f, shape: {plane: {normal: ") + normal +
                                       "}}}\n  - {name: b, shape: {sphere: 1}, position: [5, 0, 0]}\n",
                                   scene_errors::kInlineFile);
    CHECK(s.planes[0].normal.norm() == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(s.planes[0].normal.x() > 0.5);
  }
}

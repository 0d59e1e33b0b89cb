// render/frame3d/occlusion: which contact points a body hides from the camera.
#include "render/frame3d/occlusion.h"

#include <doctest/doctest.h>

using namespace sim::world3d;
using render::frame3d::hiddenByBodies;

TEST_CASE("a box on the floor hides its far lower corners from a camera above and in front, not its near ones") {
  Body box = makeBody(makeBox(Vec3(1, 1, 1)), 1.0);
  box.x = Vec3(0, 0, 0.5);
  const std::vector<Body> bodies{box};
  const Vec3 eye(0, -5, 3);
  // near corners (y = −0.5) in view; far corners (y = +0.5) behind the box
  CHECK_FALSE(hiddenByBodies(eye, Vec3(-0.5, -0.5, 0), bodies, 0.01));
  CHECK_FALSE(hiddenByBodies(eye, Vec3(0.5, -0.5, 0), bodies, 0.01));
  CHECK(hiddenByBodies(eye, Vec3(-0.5, 0.5, 0), bodies, 0.01));
  CHECK(hiddenByBodies(eye, Vec3(0.5, 0.5, 0), bodies, 0.01));
  // turned a quarter about z it is the same box: the same answer
  std::vector<Body> turned = bodies;
  turned[0].q = axisAngle(Vec3::UnitZ(), M_PI / 2);
  CHECK(hiddenByBodies(eye, Vec3(0.5, 0.5, 0), turned, 0.01));
  CHECK_FALSE(hiddenByBodies(eye, Vec3(0.5, -0.5, 0), turned, 0.01));
}

TEST_CASE("a ball hides the point it rests on from above, not from the side; a far body hides nothing") {
  Body ball = makeBody(makeSphere(0.1), 1.0);
  ball.x = Vec3(0, 0, 0.1);
  Body ellipsoid = makeBody(makeEllipsoid(Vec3(0.3, 0.1, 0.2)), 1.0);
  ellipsoid.x = Vec3(10, 0, 0.2);
  const std::vector<Body> bodies{ball, ellipsoid};
  CHECK(hiddenByBodies(Vec3(0, 0, 2), Vec3(0, 0, 0.0001), bodies, 0.01));
  CHECK_FALSE(hiddenByBodies(Vec3(0, -2, 0.0), Vec3(0, 0, 0.0001), bodies, 0.01));
  // an ellipsoid between the eye and a point hides it, by its own semi-axes
  CHECK(hiddenByBodies(Vec3(10, -3, 0.2), Vec3(10, 3, 0.2), bodies, 0.01));
  CHECK_FALSE(hiddenByBodies(Vec3(10, -3, 0.45), Vec3(10, 3, 0.45), bodies, 0.01));
}

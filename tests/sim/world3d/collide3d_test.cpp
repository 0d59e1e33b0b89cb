// Contact points in 3D (collide3d.cpp): a box's corners, a sphere's lowest point and an ellipsoid's
// support point against a plane, and two spheres, each against its hand-computed value.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/world3d/collide3d.h"

using namespace sim::world3d;

namespace {
BodyState at(const Vec3& x, const Quat& q = Quat::Identity()) {
  BodyState s;
  s.x = x, s.q = q;
  return s;
}
const Plane kFloor{Vec3::Zero(), Vec3::UnitZ()};
}  // namespace

TEST_CASE("a box lying flat touches the floor at its four lower corners; tilted about an edge, at two") {
  ContactPoint3 p[kMaxContactPoints];
  const Shape box = makeBox(Vec3(0.4, 0.2, 0.1));
  REQUIRE(planeContact(box, at(Vec3(0, 0, 0.05)), kFloor, 1e-9, p) == 4);
  for (int k = 0; k < 4; ++k) {
    CHECK(std::abs(p[k].separation) <= 1e-15);
    CHECK(std::abs(std::abs(p[k].point.x()) - 0.2) <= 1e-15);
    CHECK(std::abs(std::abs(p[k].point.y()) - 0.1) <= 1e-15);
    CHECK((p[k].feature & 4) == 0);  // the corners of the lower face
  }
  // turned 30° about the y axis and lowered until its lowest edge touches: two corners, the rest up
  const Quat q = axisAngle(Vec3::UnitY(), M_PI / 6);
  const double lowest = 0.2 * std::sin(M_PI / 6) + 0.05 * std::cos(M_PI / 6);
  REQUIRE(planeContact(box, at(Vec3(0, 0, lowest), q), kFloor, 1e-9, p) == 2);
  CHECK(std::abs(p[0].point.y() + p[1].point.y()) <= 1e-15);
  // a margin reaches the next corners up: the same end's upper edge 0.1 cos 30° = 0.087 up, the
  // lower face's far end 0.4 sin 30° = 0.2 up
  CHECK(planeContact(box, at(Vec3(0, 0, lowest), q), kFloor, 0.08, p) == 2);
  CHECK(planeContact(box, at(Vec3(0, 0, lowest), q), kFloor, 0.09, p) == 4);
  CHECK(planeContact(box, at(Vec3(0, 0, lowest), q), kFloor, 0.21, p) == 6);
}

TEST_CASE("a sphere's lowest point, an ellipsoid's support point, and a tilted plane") {
  ContactPoint3 p[kMaxContactPoints];
  REQUIRE(planeContact(makeSphere(0.3), at(Vec3(1, 2, 0.25)), kFloor, 0.0, p) == 1);
  CHECK((p[0].point - Vec3(1, 2, -0.05)).norm() <= 1e-15);
  CHECK(p[0].separation == doctest::Approx(-0.05).epsilon(1e-15));
  // an ellipsoid of semi-axes (a, b, c) = (0.3, 0.2, 0.1) turned 90° about x: its b axis points
  // up, so its lowest point is b below its center
  REQUIRE(planeContact(makeEllipsoid(Vec3(0.3, 0.2, 0.1)), at(Vec3(0, 0, 0.2), axisAngle(Vec3::UnitX(), M_PI / 2)), kFloor, 1e-9,
                       p) == 1);
  CHECK(std::abs(p[0].separation) <= 1e-15);
  CHECK(p[0].point.norm() <= 1e-15);
  // a plane through (0, 0, 1) facing (1, 0, 1)/√2: a unit sphere at the origin has its center 1/√2
  // behind it, so it is 1 + 1/√2 deep, its deepest point at −n̂
  const Plane slope{Vec3(0, 0, 1), Vec3(1, 0, 1).normalized()};
  REQUIRE(planeContact(makeSphere(1.0), at(Vec3::Zero()), slope, 0.0, p) == 1);
  CHECK(p[0].separation == doctest::Approx(-1.0 - 1.0 / std::sqrt(2.0)).epsilon(1e-15));
  CHECK((p[0].point + slope.normal).norm() <= 1e-15);
}

TEST_CASE("two spheres: the point midway between their surfaces, the normal from B to A") {
  ContactPoint3 p;
  Vec3 n;
  REQUIRE(sphereContact(at(Vec3(1, 0, 0)), 0.6, at(Vec3(0, 0, 0)), 0.5, 0.0, p, n));
  CHECK((n - Vec3::UnitX()).norm() <= 1e-15);
  CHECK(p.separation == doctest::Approx(-0.1).epsilon(1e-15));
  CHECK((p.point - Vec3(0.45, 0, 0)).norm() <= 1e-15);
  CHECK_FALSE(sphereContact(at(Vec3(2, 0, 0)), 0.6, at(Vec3(0, 0, 0)), 0.5, 0.5, p, n));
}

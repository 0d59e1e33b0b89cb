// The perspective camera: what it looks at lands on its principal point, pixels and clip
// coordinates agree, the depth range maps to [−1, 1], and a fitted camera shows all of its ball.
#include "render/draw3d/camera3d.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace render::draw3d;
using sim::core::Vec2;
using sim::world3d::Vec3;

TEST_CASE("a camera looking at a point: it lands on the principal point, right is right and up is up") {
  const Camera3d c(Vec3(0, -5, 0), Vec3::Zero(), Vec3::UnitZ(), 40.0, 640, 360, Vec2(320, 180), 1.0, 10.0);
  CHECK((c.toPixel(Vec3::Zero()) - Vec2(320, 180)).norm() < 1e-12);
  CHECK(c.toPixel(Vec3(1, 0, 0)).x() > 320);  // +x is to the right seen from −y
  CHECK(c.toPixel(Vec3(0, 0, 1)).y() < 180);  // +z is up: a smaller row
  // the focal length from the field of view: 180 px over tan 20°
  CHECK(c.focalPx() == doctest::Approx(180.0 / std::tan(20.0 * std::numbers::pi / 180.0)));
  CHECK(c.viewHeight() == doctest::Approx(2 * 5 * std::tan(20.0 * std::numbers::pi / 180.0)));
  // farther is smaller
  CHECK(c.pixelsPerMeter(10.0) == doctest::Approx(0.5 * c.pixelsPerMeter(5.0)));
}

TEST_CASE("clip coordinates agree with pixels, and the depth range maps to [−1, 1]") {
  const Camera3d c(Vec3(1, -4, 2), Vec3(0.2, 0.1, 0), Vec3::UnitZ(), 35.0, 320, 180, Vec2(140, 80), 2.0, 8.0);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.5, -0.3, 0.7), Vec3(-1, 1, -0.5)}) {
    const Vec4 clip = c.clip(p);
    const Vec2 pixel = c.toPixel(p);
    // normalized device coordinates back to pixels (GL's y up)
    CHECK((0.5 * (clip.x() / clip.w() + 1.0) * 320) == doctest::Approx(pixel.x()));
    CHECK((0.5 * (1.0 - clip.y() / clip.w()) * 180) == doctest::Approx(pixel.y()));
    CHECK(clip.w() == doctest::Approx(c.toCamera(p).z()));
    CHECK((c.clipOf(pixel, clip.w()) - clip).norm() < 1e-9);
  }
  CHECK(c.clipOf(Vec2(0, 0), 2.0).z() / 2.0 == doctest::Approx(-1.0));
  CHECK(c.clipOf(Vec2(0, 0), 8.0).z() / 8.0 == doctest::Approx(1.0));
}

TEST_CASE("a fitted camera shows the whole box in the free part of the frame, as near as its margin allows") {
  Box3d box;
  box.add(Vec3(-1, 0.5, 2.5));
  box.add(Vec3(3, 2.5, 3.2));
  // the right 200 px are a panel's, the bottom 60 a caption's
  const Camera3d c = Camera3d::fit(box, Vec3(1, -1.7, 0.9), Vec3::UnitZ(), 35.0, 0.08, 1280, 720, 1080, 660);
  // it looks at the box's center, from the principal point at the middle of the free part
  CHECK((c.toPixel(box.ball().center) - Vec2(540, 330)).norm() < 1e-9);
  double slack = 1e9;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1 ? box.max : box.min).x(), (k & 2 ? box.max : box.min).y(), (k & 4 ? box.max : box.min).z());
    const Vec2 p = c.toPixel(corner);
    // within the free part less its margin: 0.08 × 1080 and 0.08 × 660 px from its sides
    const double x = std::min(p.x() - 0.08 * 1080, 0.92 * 1080 - p.x()), y = std::min(p.y() - 0.08 * 660, 0.92 * 660 - p.y());
    CHECK(x > -1e-6);
    CHECK(y > -1e-6);
    slack = std::min({slack, x, y});
    CHECK(c.toCamera(corner).z() > c.nearDepth());
    CHECK(c.toCamera(corner).z() < c.farDepth());
  }
  // and no farther than that: a corner touches the margin
  CHECK(slack < 1e-6);
}

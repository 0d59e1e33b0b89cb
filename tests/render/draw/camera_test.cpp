// The orthographic camera: world to pixels and back, the automatic fit (aspect, margin), and the
// degenerate views that still need a scale.
#include <doctest/doctest.h>

#include "render/draw/camera.h"

using render::draw::Bounds;
using render::draw::Camera;
using sim::core::Vec2;

TEST_CASE("world and pixel coordinates: y up in the world, down in the frame") {
  const Camera c({1.0, 2.0}, 4.0, 200, 100);
  CHECK(c.pixelSize() == doctest::Approx(0.04));
  CHECK(c.worldWidth() == doctest::Approx(8.0));
  const Vec2 middle = c.toPixel({1.0, 2.0});
  CHECK(middle.x() == doctest::Approx(100.0));
  CHECK(middle.y() == doctest::Approx(50.0));
  const Vec2 topLeft = c.toPixel({-3.0, 4.0});
  CHECK(topLeft.x() == doctest::Approx(0.0));
  CHECK(topLeft.y() == doctest::Approx(0.0));
  const Vec2 back = c.toWorld(c.toPixel({0.3, -0.7}));
  CHECK(back.x() == doctest::Approx(0.3));
  CHECK(back.y() == doctest::Approx(-0.7));
  const Bounds v = c.view();
  CHECK(v.min.x() == doctest::Approx(-3.0));
  CHECK(v.max.y() == doctest::Approx(4.0));
}

TEST_CASE("the automatic fit keeps the frame's aspect and leaves the margin free") {
  Bounds b;
  b.add({0.0, 0.0});
  b.add({1.0, 4.0});  // tall content in a wide frame: the height decides
  const Camera tall = Camera::fit(b, 0.1, 160, 90);
  CHECK(tall.worldHeight() == doctest::Approx(4.0 / 0.8));
  CHECK(tall.center().x() == doctest::Approx(0.5));
  CHECK(tall.center().y() == doctest::Approx(2.0));
  Bounds w;
  w.add({-8.0, 0.0});
  w.add({8.0, 1.0});  // wide content: the width decides
  const Camera wide = Camera::fit(w, 0.0, 160, 90);
  CHECK(wide.worldWidth() == doctest::Approx(16.0));
  // everything fitted lies inside the frame
  for (const Vec2& p : {w.min, w.max}) {
    const Vec2 px = wide.toPixel(p);
    CHECK(px.x() >= -1e-9);
    CHECK(px.x() <= 160 + 1e-9);
    CHECK(px.y() >= -1e-9);
    CHECK(px.y() <= 90 + 1e-9);
  }
}

TEST_CASE("nothing or a single point still gets a view") {
  const Camera none = Camera::fit(Bounds{}, 0.1, 100, 100);
  CHECK(none.worldHeight() == doctest::Approx(2.0));
  Bounds p;
  p.add({3.0, 4.0});
  const Camera point = Camera::fit(p, 0.1, 100, 100);
  CHECK(point.worldHeight() == doctest::Approx(2.0));
  CHECK(point.center().x() == doctest::Approx(3.0));
}

// 3D solids drawn with GL: shaded in their body's color with the light telling faces apart, on the
// background, the nearer of two solids in front whatever the order they are drawn in, outlines
// darker than faces, and the overlay over everything.
#include "render/draw3d/gl_canvas3d.h"

#include <doctest/doctest.h>

using namespace render::draw3d;
using namespace render::draw;
using sim::core::Vec2;
using sim::world3d::Mat3;
using sim::world3d::Vec3;

namespace {

constexpr int kWidth = 160, kHeight = 90;

struct Rgb {
  int r, g, b;
};
Rgb at(const Image& image, const Vec2& pixel) {
  const uint8_t* p = image.pixel(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
  return {p[0], p[1], p[2]};
}

Style twoColors() {
  Style s;
  s.bodies = {Color::parse("#d62728"), Color::parse("#1f77b4")};
  s.lineWidth = 4.0;  // outlines 3 px wide: a pixel on a crease is all outline
  return s;
}

}  // namespace

TEST_CASE("a box in perspective: reddish faces of three brightnesses on a white background") {
  GlContext gl(kWidth, kHeight);
  TextRenderer text;
  const Style style = twoColors();
  const Camera3d camera(Vec3(3, -4, 2.5), Vec3::Zero(), Vec3::UnitZ(), 35.0, kWidth, kHeight, Vec2(80, 45), 1.0, 20.0);
  GlCanvas3d canvas(gl, text, style);
  canvas.begin(camera);
  canvas.solid(boxMesh(Vec3(1, 1, 1)), Vec3::Zero(), Mat3::Identity(), {Role::Body, 0, 1.0});
  const Image image = canvas.finish();
  // the three faces seen from (3, −4, 2.5): +x, −y and +z, each at a point inside it
  const Rgb right = at(image, camera.toPixel(Vec3(0.5, 0, 0))), front = at(image, camera.toPixel(Vec3(0, -0.5, 0))),
            top = at(image, camera.toPixel(Vec3(0, 0, 0.5)));
  for (const Rgb& c : {right, front, top}) {
    CHECK(c.r > c.g + 40);
    CHECK(c.r > c.b + 40);
  }
  CHECK(right.r != front.r);
  CHECK(front.r != top.r);
  CHECK(right.r != top.r);
  // the background in a corner
  const Rgb corner = at(image, Vec2(2, 2));
  CHECK(corner.r == 255);
  CHECK(corner.g == 255);
  CHECK(corner.b == 255);
  // the outline at a crease between two faces is darker than both
  const Rgb crease = at(image, camera.toPixel(Vec3(0.5, -0.5, 0)));
  CHECK(crease.r < std::min(right.r, front.r));
}

TEST_CASE("the depth buffer: the nearer box in front whatever the drawing order; the overlay over both") {
  GlContext gl(kWidth, kHeight);
  TextRenderer text;
  const Style style = twoColors();
  const Camera3d camera(Vec3(0, -6, 0), Vec3::Zero(), Vec3::UnitZ(), 35.0, kWidth, kHeight, Vec2(80, 45), 1.0, 20.0);
  for (bool nearFirst : {true, false}) {
    CAPTURE(nearFirst);
    GlCanvas3d canvas(gl, text, style);
    canvas.begin(camera);
    // body 1 (blue) nearer the eye, body 0 (red) behind it and larger
    auto nearBox = [&] { canvas.solid(boxMesh(Vec3(1, 1, 1)), Vec3(0, -1, 0), Mat3::Identity(), {Role::Body, 1, 1.0}); };
    auto farBox = [&] { canvas.solid(boxMesh(Vec3(2, 2, 2)), Vec3(0, 1, 0), Mat3::Identity(), {Role::Body, 0, 1.0}); };
    if (nearFirst) nearBox(), farBox();
    else farBox(), nearBox();
    // a black segment across the middle, over both
    canvas.overlay().segment(Vec2(0, 30), Vec2(kWidth, 30), {Role::Velocity, -1, 1.0});
    const Image image = canvas.finish();
    const Rgb middle = at(image, Vec2(80, 45));
    CHECK(middle.b > middle.r + 40);  // blue, the near box
    const Rgb beside = at(image, camera.toPixel(Vec3(0.85, 0, 0.85)));
    CHECK(beside.r > beside.b + 40);  // red, the far box around it
    const Rgb line = at(image, Vec2(80, kHeight - 30));
    CHECK(line.r < 80);
  }
}

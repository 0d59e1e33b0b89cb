// Images in memory: the box filter of supersampling, pasting panels, flipping GL's rows.
#include <doctest/doctest.h>

#include "render/draw/image.h"

using render::draw::Color;
using render::draw::Image;

TEST_CASE("a new image is filled with its color") {
  const Image i(3, 2, {1.0, 0.0, 0.5, 1.0});
  REQUIRE(i.rgba.size() == 24);
  CHECK(i.pixel(2, 1)[0] == 255);
  CHECK(i.pixel(2, 1)[1] == 0);
  CHECK(i.pixel(2, 1)[2] == 128);
  CHECK(i.pixel(2, 1)[3] == 255);
}

TEST_CASE("downsampling averages each block, rounded") {
  Image i(4, 2, {0.0, 0.0, 0.0, 1.0});
  // the left 2×2 block: one white pixel of four → 63.75, rounded to 64
  i.pixel(0, 0)[0] = 255;
  // the right block: all 10
  for (int y = 0; y < 2; ++y)
    for (int x = 2; x < 4; ++x) i.pixel(x, y)[1] = 10;
  const Image d = render::draw::downsample(i, 2);
  CHECK(d.width == 2);
  CHECK(d.height == 1);
  CHECK(d.pixel(0, 0)[0] == 64);
  CHECK(d.pixel(1, 0)[1] == 10);
  CHECK(d.pixel(1, 0)[3] == 255);
  CHECK(render::draw::downsample(i, 1) == i);
}

TEST_CASE("pasting is clipped to the target") {
  Image target(4, 4, {0.0, 0.0, 0.0, 1.0});
  const Image red(3, 3, {1.0, 0.0, 0.0, 1.0});
  render::draw::paste(red, target, 2, -1);
  CHECK(target.pixel(2, 0)[0] == 255);
  CHECK(target.pixel(3, 1)[0] == 255);
  CHECK(target.pixel(3, 2)[0] == 0);
  CHECK(target.pixel(1, 0)[0] == 0);
  render::draw::paste(red, target, 10, 10);  // wholly outside: nothing
}

TEST_CASE("colors parse from #rrggbb and mix") {
  const Color c = Color::parse("#ff8000");
  CHECK(c.r == 1.0);
  CHECK(c.g == doctest::Approx(128.0 / 255.0));
  CHECK(c.b == 0.0);
  CHECK(Color::byte(c.mixed({0.0, 0.0, 0.0, 1.0}, 0.5).r) == 128);
  CHECK_THROWS_AS(Color::parse("red"), std::invalid_argument);
}

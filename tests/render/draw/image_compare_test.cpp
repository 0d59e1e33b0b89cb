// Frames compared with the golden tolerance: a channel within it is the same pixel, one past it
// differs; the frame passes up to the allowed fraction of differing pixels, not one more.
#include <doctest/doctest.h>

#include "render/draw/image_compare.h"

using namespace render::draw;

TEST_CASE("a pixel differs past the channel tolerance; the frame past the fraction") {
  const Image expected(100, 10, {0.5, 0.5, 0.5, 1.0});  // 1000 pixels: 0.2% allows 2
  Image actual = expected;
  actual.pixel(3, 3)[1] += 24;
  ImageComparison c = compareImages(expected, actual);
  CHECK(c.differing == 0);
  CHECK(c.largest == 24);
  CHECK(c.passed());
  actual.pixel(3, 3)[1] += 1;
  actual.pixel(4, 3)[0] -= 100;
  c = compareImages(expected, actual);
  CHECK(c.differing == 2);
  CHECK(c.allowed == 2);
  CHECK(c.passed());
  // the diff marks the differing pixels in red, the others gray
  CHECK(c.diff.pixel(3, 3)[0] == 255);
  CHECK(c.diff.pixel(3, 3)[1] == 0);
  CHECK(c.diff.pixel(0, 0)[0] == c.diff.pixel(0, 0)[1]);
  actual.pixel(5, 3)[2] += 30;
  CHECK_FALSE(compareImages(expected, actual).passed());
  CHECK(compareImages(expected, actual, {30, 0.002}).passed());
}

TEST_CASE("frames of another size differ") {
  const ImageComparison c = compareImages(Image(10, 10), Image(10, 12));
  CHECK_FALSE(c.sameSize);
  CHECK_FALSE(c.passed());
}

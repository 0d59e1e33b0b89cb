// The dot layer: a dot covers its polygon's area at the sample positions it is given, centered where
// it is placed; a run of one color covers each sample once; later colors lie over earlier ones;
// dots past the frame's edges are cut; the positions are the frame's (GL's, flipped to y down).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "render/draw/dot_layer.h"

using namespace render::draw;
using sim::core::Vec2;

namespace {

const Color kBlack{0.0, 0.0, 0.0, 1.0};
const Color kWhite{1.0, 1.0, 1.0, 1.0};

// sixteen positions a pixel on a 4 × 4 grid: symmetric, and fine enough to measure areas with
const std::vector<SamplePosition> kGrid = [] {
  std::vector<SamplePosition> g;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) g.push_back({(i + 0.5) / 4, (j + 0.5) / 4});
  return g;
}();

// how much of each pixel a black dot covers on white, summed: its area in pixels
double coveredArea(const Image& i) {
  double area = 0.0;
  for (int y = 0; y < i.height; ++y)
    for (int x = 0; x < i.width; ++x) area += (255.0 - i.pixel(x, y)[0]) / 255.0;
  return area;
}

// the coverage-weighted mean of the pixels' centers
Vec2 centroid(const Image& i) {
  Vec2 sum = Vec2::Zero();
  double weight = 0.0;
  for (int y = 0; y < i.height; ++y)
    for (int x = 0; x < i.width; ++x) {
      const double w = (255.0 - i.pixel(x, y)[0]) / 255.0;
      sum += w * Vec2(x + 0.5, y + 0.5);
      weight += w;
    }
  return sum / weight;
}

}  // namespace

TEST_CASE("a dot covers its polygon's area, centered where it was placed, and nothing past its circle") {
  struct Case {
    double radius;
    int corners;
    double epsilon;  // 16 samples a pixel: each edge pixel within 1/32 of its share
  };
  for (const Case& c : {Case{0.8, 4, 0.1}, Case{3.0, 8, 0.03}, Case{7.5, 40, 0.02}}) {
    CAPTURE(c.radius);
    Image frame(40, 40, kWhite);
    DotLayer dots;
    dots.add({17.3, 21.6}, c.radius, c.corners, kBlack);
    dots.drawInto(frame, kGrid);
    const double area = 0.5 * c.corners * c.radius * c.radius * std::sin(2.0 * std::numbers::pi / c.corners);
    CHECK(coveredArea(frame) == doctest::Approx(area).epsilon(c.epsilon));
    CHECK((centroid(frame) - Vec2(17.3, 21.6)).norm() < 0.05);
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        // a pixel wholly outside the polygon's circle untouched, and its alpha left alone everywhere
        const double nearX = std::clamp(17.3, double(x), x + 1.0), nearY = std::clamp(21.6, double(y), y + 1.0);
        if (std::hypot(nearX - 17.3, nearY - 21.6) >= c.radius) CHECK(frame.pixel(x, y)[0] == 255);
        CHECK(frame.pixel(x, y)[3] == 255);
      }
  }
  // a pixel wholly inside takes the dot's color exactly
  Image frame(20, 20, kWhite);
  DotLayer dots;
  dots.add({10.0, 10.0}, 4.0, 12, Color::parse("#d62728"));
  dots.drawInto(frame, samplePositions(4, 1));
  CHECK(frame.pixel(10, 10)[0] == 0xd6);
  CHECK(frame.pixel(10, 10)[1] == 0x27);
  CHECK(frame.pixel(10, 10)[2] == 0x28);
}

TEST_CASE("a dot with a corner at angle 0 is symmetric about its center, across and along") {
  Image frame(21, 21, kWhite);
  DotLayer dots;
  dots.add({10.5, 10.5}, 5.3, 8, kBlack);
  dots.drawInto(frame, kGrid);
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 21; ++x) {
      const uint8_t v = frame.pixel(x, y)[0];
      CHECK(frame.pixel(20 - x, y)[0] == v);
      CHECK(frame.pixel(x, 20 - y)[0] == v);
      CHECK(frame.pixel(y, x)[0] == v);
    }
  // a square (4 corners, at 0°, 90°, ...) is a diamond: its corner pixels on the axes, none on the diagonals
  Image diamond(21, 21, kWhite);
  DotLayer d;
  d.add({10.5, 10.5}, 8.0, 4, kBlack);
  d.drawInto(diamond, kGrid);
  CHECK(diamond.pixel(17, 10)[0] == 0);
  CHECK(diamond.pixel(16, 16)[0] == 255);
}

TEST_CASE("opaque dots of one color in a row cover a sample once, translucent ones blend each; later lie over earlier") {
  // the same opaque dot twice is that dot, pixel for pixel
  Image once(30, 30, kWhite), twice(30, 30, kWhite);
  DotLayer one, two;
  one.add({14.2, 15.7}, 4.4, 9, kBlack);
  two.add({14.2, 15.7}, 4.4, 9, kBlack);
  two.add({14.2, 15.7}, 4.4, 9, kBlack);
  one.drawInto(once, samplePositions(4, 1));
  two.drawInto(twice, samplePositions(4, 1));
  CHECK(once == twice);
  // half opaque black over white: the covered pixels are halfway, and a quarter left under two
  Image half(30, 30, kWhite), halfTwice(30, 30, kWhite);
  DotLayer h, hh;
  h.add({15.0, 15.0}, 6.0, 16, kBlack.withAlpha(0.5));
  hh.add({15.0, 15.0}, 6.0, 16, kBlack.withAlpha(0.5));
  hh.add({15.0, 15.0}, 6.0, 16, kBlack.withAlpha(0.5));
  h.drawInto(half, samplePositions(2, 1));
  hh.drawInto(halfTwice, samplePositions(2, 1));
  CHECK(half.pixel(15, 15)[0] == 128);
  CHECK(halfTwice.pixel(15, 15)[0] == 64);
  // red, then blue over it at the same place: blue wherever blue covers all of a pixel
  Image frame(30, 30, kWhite);
  DotLayer both;
  both.add({15.0, 15.0}, 6.0, 16, Color{1.0, 0.0, 0.0, 1.0});
  both.add({15.0, 15.0}, 3.0, 16, Color{0.0, 0.0, 1.0, 1.0});
  both.drawInto(frame, samplePositions(4, 1));
  CHECK(frame.pixel(15, 15)[2] == 255);
  CHECK(frame.pixel(15, 15)[0] == 0);
  CHECK(frame.pixel(15, 10)[0] == 255);  // red between the two radii
  CHECK(frame.pixel(15, 10)[2] == 0);
}

TEST_CASE("dots past the frame's edges are cut at them; a dot of no size, place or color draws nothing") {
  Image frame(10, 10, kWhite);
  DotLayer dots;
  dots.add({0.0, 5.0}, 3.0, 40, kBlack);    // half of it off the left edge
  dots.add({1e300, 5.0}, 3.0, 40, kBlack);  // far off
  dots.add({5.0, NAN}, 3.0, 40, kBlack);
  dots.add({5.0, 5.0}, 0.0, 40, kBlack);
  dots.add({5.0, 5.0}, -1.0, 40, kBlack);
  dots.add({5.0, 5.0}, 3.0, 2, kBlack);
  dots.add({5.0, 5.0}, 3.0, 40, Color{NAN, 0.0, 0.0, 1.0});
  dots.add({5.0, 5.0}, 3.0, 40, kBlack.withAlpha(0.0));
  dots.drawInto(frame, kGrid);
  const double half = 0.25 * 40 * 9.0 * std::sin(2.0 * std::numbers::pi / 40);
  CHECK(coveredArea(frame) == doctest::Approx(half).epsilon(0.03));
  // the right half of the frame untouched (the dot at x = 0 reaches x = 3)
  for (int y = 0; y < 10; ++y)
    for (int x = 4; x < 10; ++x) CHECK(frame.pixel(x, y)[0] == 255);
  // a dot far larger than the frame, centered far off, covers the frame without overflowing
  Image huge(10, 10, kWhite);
  DotLayer big;
  big.add({5.0, 1e160}, 1e170, 40, kBlack);
  big.drawInto(huge, kGrid);
  CHECK(coveredArea(huge) == doctest::Approx(100.0));
}

TEST_CASE("the sample positions are GL's, from the pixel's top-left corner, y down, and at most 16") {
  const std::vector<SamplePosition> four = samplePositions(4, 1);
  REQUIRE(four.size() == 4);
  // llvmpipe's first position (0.375, 0.125) from the lower-left corner, y up
  CHECK(four[0][0] == 0.375);
  CHECK(four[0][1] == 0.875);
  CHECK(samplePositions(2, 1).size() == 2);
  CHECK(samplePositions(1, 1) == std::vector<SamplePosition>{{0.5, 0.5}});
  // supersampled twice: each quarter of the pixel has the four, scaled into it
  const std::vector<SamplePosition> sixteen = samplePositions(4, 2);
  REQUIRE(sixteen.size() == 16);
  for (const SamplePosition& p : sixteen) CHECK((p[0] > 0.0 && p[0] < 1.0 && p[1] > 0.0 && p[1] < 1.0));
  CHECK(sixteen[4][0] == doctest::Approx(0.5 + 0.375 / 2));
  CHECK_THROWS(samplePositions(2, 3));
  Image frame(4, 4, kWhite);
  CHECK_THROWS(DotLayer().drawInto(frame, {}));
}

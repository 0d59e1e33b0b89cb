// The dot layer: a disc's coverage is its area to the 16 samples' resolution, centered where it is
// placed; a run of one color covers each sample once; later colors lie over earlier ones; dots
// past the frame's edges are cut, not drawn wrapped or out of bounds.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "render/draw/dot_layer.h"

using namespace render::draw;
using sim::core::Vec2;

namespace {

const Color kBlack{0.0, 0.0, 0.0, 1.0};
const Color kWhite{1.0, 1.0, 1.0, 1.0};

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

TEST_CASE("a dot covers its disc's area, centered where it was placed, and nothing past its radius") {
  for (const double r : {0.8, 3.0, 7.5}) {
    CAPTURE(r);
    Image frame(40, 40, kWhite);
    DotLayer dots;
    dots.add({17.3, 21.6}, r, kBlack);
    dots.drawInto(frame);
    // 16 samples a pixel: each edge pixel's coverage is within 1/32 of its share, on average far less
    CHECK(coveredArea(frame) == doctest::Approx(std::numbers::pi * r * r).epsilon(0.03));
    CHECK((centroid(frame) - Vec2(17.3, 21.6)).norm() < 0.05);
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        // a pixel wholly outside the disc untouched, and its alpha left alone everywhere
        const double nearX = std::clamp(17.3, double(x), x + 1.0), nearY = std::clamp(21.6, double(y), y + 1.0);
        if (std::hypot(nearX - 17.3, nearY - 21.6) >= r) CHECK(frame.pixel(x, y)[0] == 255);
        CHECK(frame.pixel(x, y)[3] == 255);
      }
  }
  // a pixel wholly inside takes the dot's color exactly
  Image frame(20, 20, kWhite);
  DotLayer dots;
  dots.add({10.0, 10.0}, 4.0, Color::parse("#d62728"));
  dots.drawInto(frame);
  CHECK(frame.pixel(10, 10)[0] == 0xd6);
  CHECK(frame.pixel(10, 10)[1] == 0x27);
  CHECK(frame.pixel(10, 10)[2] == 0x28);
}

TEST_CASE("a dot is symmetric about its center") {
  Image frame(21, 21, kWhite);
  DotLayer dots;
  dots.add({10.5, 10.5}, 5.3, kBlack);
  dots.drawInto(frame);
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 21; ++x) {
      const uint8_t v = frame.pixel(x, y)[0];
      CHECK(frame.pixel(20 - x, y)[0] == v);
      CHECK(frame.pixel(x, 20 - y)[0] == v);
      CHECK(frame.pixel(y, x)[0] == v);
    }
}

TEST_CASE("dots of one color in a row cover a sample once; a later color lies over an earlier") {
  // the same dot twice is that dot, pixel for pixel, even half opaque
  for (const double alpha : {1.0, 0.5}) {
    Image once(30, 30, kWhite), twice(30, 30, kWhite);
    DotLayer one, two;
    one.add({14.2, 15.7}, 4.4, kBlack.withAlpha(alpha));
    two.add({14.2, 15.7}, 4.4, kBlack.withAlpha(alpha));
    two.add({14.2, 15.7}, 4.4, kBlack.withAlpha(alpha));
    one.drawInto(once);
    two.drawInto(twice);
    CHECK(once == twice);
  }
  // half opaque black over white: the covered pixels are halfway
  Image half(30, 30, kWhite);
  DotLayer h;
  h.add({15.0, 15.0}, 6.0, kBlack.withAlpha(0.5));
  h.drawInto(half);
  CHECK(half.pixel(15, 15)[0] == 128);
  // red, then blue over it at the same place: blue wherever blue covers all of a pixel
  Image frame(30, 30, kWhite);
  DotLayer both;
  both.add({15.0, 15.0}, 6.0, Color{1.0, 0.0, 0.0, 1.0});
  both.add({15.0, 15.0}, 3.0, Color{0.0, 0.0, 1.0, 1.0});
  both.drawInto(frame);
  CHECK(frame.pixel(15, 15)[2] == 255);
  CHECK(frame.pixel(15, 15)[0] == 0);
  CHECK(frame.pixel(15, 10)[0] == 255);  // red between the two radii
  CHECK(frame.pixel(15, 10)[2] == 0);
}

TEST_CASE("dots past the frame's edges are cut at them; a dot of no size or no place draws nothing") {
  Image frame(10, 10, kWhite);
  DotLayer dots;
  dots.add({0.0, 5.0}, 3.0, kBlack);    // half of it off the left edge
  dots.add({1e300, 5.0}, 3.0, kBlack);  // far off
  dots.add({5.0, NAN}, 3.0, kBlack);
  dots.add({5.0, 5.0}, 0.0, kBlack);
  dots.add({5.0, 5.0}, -1.0, kBlack);
  dots.drawInto(frame);
  CHECK(coveredArea(frame) == doctest::Approx(0.5 * std::numbers::pi * 9.0).epsilon(0.03));
  // the right half of the frame untouched (the dot at x = 0 reaches x = 3)
  for (int y = 0; y < 10; ++y)
    for (int x = 4; x < 10; ++x) CHECK(frame.pixel(x, y)[0] == 255);
}

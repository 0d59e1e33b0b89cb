// The outline of a body made of parts (part_outline.cpp): the union's boundary, nothing where two
// parts touch.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/describe/part_outline.h"

namespace {

using sim::core::Vec2;

double length(const std::vector<sim::describe::OutlineSegment>& outline) {
  double sum = 0.0;
  for (const sim::describe::OutlineSegment& s : outline) sum += (s.b - s.a).norm();
  return sum;
}

}  // namespace

TEST_CASE("two boxes side by side: the outline of the 3 × 1 box they make, no seam") {
  const sim::core::Shape s =
      sim::core::makeCompound({{sim::core::makeBox(2, 1), {}}, {sim::core::makeBox(1, 1), {{1.5, 0}, {}}}});
  const auto outline = sim::describe::partOutline(s);
  CHECK(length(outline) == doctest::Approx(8.0).epsilon(1e-8));
  // nothing on the line x = 1 where they touch, but for the ends of the top and bottom edges
  for (const sim::describe::OutlineSegment& seg : outline)
    CHECK_FALSE((std::abs(seg.a.x() - 1.0) < 1e-9 && std::abs(seg.b.x() - 1.0) < 1e-9));
}

TEST_CASE("an L of two boxes: its six sides, the shared part of the long edge left out") {
  // a 2 × 1 box and a 1 × 1 box on top of its left half: an L of perimeter 2 + 2 + 1 + 1 + 1 + 1
  const sim::core::Shape s =
      sim::core::makeCompound({{sim::core::makeBox(2, 1), {}}, {sim::core::makeBox(1, 1), {{-0.5, 1}, {}}}});
  CHECK(length(sim::describe::partOutline(s)) == doctest::Approx(8.0).epsilon(1e-8));
}

TEST_CASE("a disk on a box's end: the arc inside the box is left out") {
  // a unit disk centred on the right end of a 2 × 1 box: the box's right edge is inside the disk,
  // and so is the arc over the box's end
  const sim::core::Shape s =
      sim::core::makeCompound({{sim::core::makeBox(2, 1), {}}, {sim::core::makeCircle(1.0), {{1, 0}, {}}}});
  const auto outline = sim::describe::partOutline(s, 720);
  for (const sim::describe::OutlineSegment& seg : outline) {
    // no piece of the box inside the disk; no piece of the disk inside the box
    const Vec2 mid = 0.5 * (seg.a + seg.b);
    const bool inBox = std::abs(mid.x()) < 1.0 - 1e-6 && std::abs(mid.y()) < 0.5 - 1e-6;
    const bool inDisk = (mid - Vec2(1, 0)).norm() < 1.0 - 1e-3;
    CHECK_FALSE(inBox);
    CHECK_FALSE(inDisk);
  }
  // the box's left side, its top and bottom out to the disk (x from −1 to 1 − √0.75 each), and the
  // disk's arc outside the box: 2π less the arc facing the box, from 150° to 210°
  const double boxPart = 1.0 + 2.0 * (2.0 - std::sqrt(0.75));
  const double arcInside = 2.0 * std::asin(0.5);
  CHECK(length(outline) == doctest::Approx(boxPart + 2.0 * M_PI - arcInside).epsilon(1e-4));
}

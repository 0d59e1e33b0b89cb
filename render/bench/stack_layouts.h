// Stack layouts shared by rigidreel and its peer engines (Box2D 2.4 in stack_bench.cpp), free of
// either engine's types, and the measures that say whether a stack held: one layout is built in
// each engine from the same numbers, run with the same settings, and measured the same way.
//
// Box2D's pyramid benchmark (its testbed's "Pyramid"; Catto's benchmark settings): rows of 1 m
// boxes 1.125 m apart, each row 0.5625 m right of the one below, on a static ground box.
//
//        [ ]                row base-1
//      [ ] [ ]
//    [ ] [ ] [ ]            row r: base - r boxes, x = -7 + 0.5625 r + 1.125 j
//  ==============  ground   top at y = 0
//
// touching: rows rest on each other (y = 0.5 + r), so the pyramid must only stand;
// dropped:  Box2D's own layout (y = 0.75 + 1.25 r), each row 0.25 m above the one below, so it
//           falls into place. A box rests at its start x in both, so |x − rest x| is the bulge.
// packed:   Box2D v3's large_pyramid benchmark (its shared/benchmarks.c, the scene b3_pyramid
//           builds): the boxes of a row side by side, touching (1 m apart), each row 0.5 m right of
//           the one below, x = 0.5 (r + 1) + j − 0.5 base, resting (y = 0.5 + r). Its rows also
//           touch sideways, half as many contacts again as the touching layout's.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bench {

// one box: where it starts and where it should end up
struct BoxPlacement {
  double x = 0.0, y = 0.0;          // center at the start, m
  double restX = 0.0, restY = 0.0;  // center when the stack holds, m (before any slop)
};

// the numbers both engines are given: Box2D's benchmark settings unless changed
struct StackSettings {
  double gravity = -10.0;  // m/s², along y
  double dt = 1.0 / 60.0;  // s
  int velocityIterations = 8;
  int positionIterations = 3;
  double friction = 0.6;
  double restitution = 0.0;
  double density = 1.0;  // kg/m²; every box alike, so only ratios of mass matter
};

struct StackLayout {
  std::string name;                 // e.g. "pyramid100-touching"
  double boxSize = 1.0;             // side of every box, m
  double groundHalfWidth = 40;      // the ground is a static box of this half width, 1 m thick,
  double groundCenterX = 0.0;       // with its top at y = 0
  std::vector<BoxPlacement> boxes;  // bottom row first, the top box last
  bool dropped = false;             // rows start apart: judge by |x − rest x|, not by the top box
};

// Box2D's pyramid of `base` boxes on the bottom row (base (base + 1) / 2 boxes in all)
inline StackLayout pyramid(int base, bool dropped, bool packed = false) {
  StackLayout l;
  l.name = "pyramid" + std::to_string(base) + (packed ? "-packed" : dropped ? "-dropped" : "-touching");
  l.dropped = dropped && !packed;
  const double left = packed ? 0.5 - 0.5 * base : -7.0, step = packed ? 1.0 : 1.125, shift = packed ? 0.5 : 0.5625,
               rise = l.dropped ? 1.25 : 1.0;
  // the ground reaches 40 m past the pyramid on each side, as the testbed's 80 m ground does at base 20
  const double right = left + step * (base - 1);
  l.groundCenterX = 0.5 * (left + right);
  l.groundHalfWidth = 0.5 * (right - left) + 40.0;
  for (int row = 0; row < base; ++row)
    for (int j = 0; j < base - row; ++j) {
      BoxPlacement b;
      b.x = b.restX = left + shift * row + step * j;
      b.y = (l.dropped ? 0.75 : 0.5) + rise * row;
      b.restY = 0.5 + row;
      l.boxes.push_back(b);
    }
  return l;
}

// a column of `height` touching boxes
inline StackLayout stack(int height) {
  StackLayout l;
  l.name = "stack" + std::to_string(height);
  for (int k = 0; k < height; ++k) l.boxes.push_back({0.0, 0.5 + k, 0.0, 0.5 + k});
  return l;
}

// what one engine reports for one body at the end: position and velocity of its center
struct BodyEnd {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, omega = 0.0;
};

// how well a stack held, from the boxes' final states (same order as layout.boxes)
struct StackMetrics {
  double topDisplacement = 0.0;  // |p − p_rest| of the top box, m (the start, when touching)
  double maxOffRestX = 0.0;      // max over boxes of |x − rest x|, m: the bulge
  double fastestSpeed = 0.0;     // max over boxes of |v|, m/s
  double fastestSpin = 0.0;      // max over boxes of |ω|, rad/s
  int moved = 0;                 // boxes more than 0.1 m from their rest x or 0.5 m below their rest y
};

inline StackMetrics measure(const StackLayout& layout, const std::vector<BodyEnd>& end) {
  StackMetrics m;
  for (size_t i = 0; i < layout.boxes.size(); ++i) {
    const BoxPlacement& b = layout.boxes[i];
    const BodyEnd& e = end[i];
    const double offX = std::abs(e.x - b.restX);
    m.maxOffRestX = std::max(m.maxOffRestX, offX);
    m.fastestSpeed = std::max(m.fastestSpeed, std::hypot(e.vx, e.vy));
    m.fastestSpin = std::max(m.fastestSpin, std::abs(e.omega));
    m.moved += offX > 0.1 || e.y < b.restY - 0.5;
  }
  if (!end.empty()) {
    const BoxPlacement& top = layout.boxes.back();
    m.topDisplacement = std::hypot(end.back().x - top.restX, end.back().y - top.restY);
  }
  return m;
}

}  // namespace bench

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
// arch:     the Arch of Box2D's samples and Solver2D (Catto; scenes/arch.yaml): 16 trapezoids and a
//           keystone, four 4 m × 1 m blocks on top, resting on the ground box; nothing holds it but
//           friction and the normal forces through long chains of contacts with large mass ratios.
//           The top block's drop is what the arch gave.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace bench {

// a point of a polygon, m
using Point = std::array<double, 2>;

// one body: where it starts and where it should end up
struct BoxPlacement {
  double x = 0.0, y = 0.0;          // center at the start, m
  double restX = 0.0, restY = 0.0;  // center when the stack holds, m (before any slop)
  std::vector<Point> polygon;       // counterclockwise about the center of mass; empty: a box of the layout's size
  double density = 1.0;             // times the settings' density
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
  // ours stands on a half-plane (y ≥ 0) instead of the ground box, as users write a floor; the peers
  // keep their ground box (Box2D v3's b3_pyramid has no other)
  bool halfPlane = false;
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

// a convex counterclockwise polygon with every edge moved outward by `distance` (inward when it is
// negative): each vertex moves by the m with m·n₁ = m·n₂ = distance, n₁ and n₂ its two edges'
// outward normals, so a polygon inset by Box2D's skin is the core whose rounding is the polygon
inline std::vector<Point> offsetPolygon(const std::vector<Point>& polygon, double distance) {
  const size_t n = polygon.size();
  auto normal = [&](size_t i) {
    const Point &p = polygon[i], &q = polygon[(i + 1) % n];
    const double dx = q[0] - p[0], dy = q[1] - p[1], length = std::hypot(dx, dy);
    return Point{dy / length, -dx / length};
  };
  std::vector<Point> out;
  for (size_t i = 0; i < n; ++i) {
    const Point n1 = normal((i + n - 1) % n), n2 = normal(i);
    const double scale = distance / (1.0 + n1[0] * n2[0] + n1[1] * n2[1]);
    out.push_back({polygon[i][0] + scale * (n1[0] + n2[0]), polygon[i][1] + scale * (n1[1] + n2[1])});
  }
  return out;
}

// a column of `height` touching boxes, the top one `topDensity` times as dense as the others (a
// heavy box on light ones: scenes/mass_ratio_stack.yaml)
inline StackLayout stack(int height, double topDensity = 1.0) {
  StackLayout l;
  l.name = "stack" + std::to_string(height);
  if (topDensity != 1.0) {
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%g", topDensity);
    l.name += std::string("-top") + ratio;
  }
  for (int k = 0; k < height; ++k) l.boxes.push_back({0.0, 0.5 + k, 0.0, 0.5 + k, {}, k == height - 1 ? topDensity : 1.0});
  return l;
}

// the Arch of Box2D's samples (Box2D v3's samples/sample_stacking.cpp, Solver2D's Arch): the inner
// and outer outlines of its right leg at a quarter of the sample's numbers, mirrored for the left
inline StackLayout arch() {
  const Point inner[9] = {{16.0, 0.0},
                          {14.93803712795643, 5.133601056842984},
                          {13.79871746027416, 10.24928069555078},
                          {12.56252963284711, 15.34107019122473},
                          {11.20040987372525, 20.39856541571217},
                          {9.66521217819836, 25.40369899225096},
                          {7.87179930638133, 30.3179337000085},
                          {5.635199558196225, 35.03820717801641},
                          {2.405937953536585, 39.09554102558315}};
  const Point outer[9] = {{24.0, 0.0},
                          {22.33619528222415, 6.02299846205841},
                          {20.54936888969905, 12.00964361211476},
                          {18.60854610798073, 17.9470321677465},
                          {16.46769273811807, 23.81367936585418},
                          {14.05325025774858, 29.57079353071012},
                          {11.23551045834022, 35.13775818285372},
                          {7.752568160730571, 40.30450679009583},
                          {3.016931552701656, 44.28891593799322}};
  auto scaled = [](Point p, double sx) { return Point{0.25 * sx * p[0], 0.25 * p[1]}; };
  StackLayout l;
  l.name = "arch";
  // a body from its outline in world coordinates, counterclockwise: placed at its centroid
  auto add = [&l](std::vector<Point> world) {
    double area = 0.0, cx = 0.0, cy = 0.0;
    for (size_t i = 0; i < world.size(); ++i) {
      const Point &p = world[i], &q = world[(i + 1) % world.size()];
      const double a = p[0] * q[1] - q[0] * p[1];
      area += 0.5 * a, cx += (p[0] + q[0]) * a / 6.0, cy += (p[1] + q[1]) * a / 6.0;
    }
    cx /= area, cy /= area;
    BoxPlacement b{cx, cy, cx, cy, {}};
    for (const Point& p : world) b.polygon.push_back({p[0] - cx, p[1] - cy});
    l.boxes.push_back(b);
  };
  for (int i = 0; i < 8; ++i) add({scaled(inner[i], 1), scaled(outer[i], 1), scaled(outer[i + 1], 1), scaled(inner[i + 1], 1)});
  for (int i = 0; i < 8; ++i)
    add({scaled(outer[i], -1), scaled(inner[i], -1), scaled(inner[i + 1], -1), scaled(outer[i + 1], -1)});
  add({scaled(inner[8], 1), scaled(outer[8], 1), scaled(outer[8], -1), scaled(inner[8], -1)});
  // the four blocks on the keystone, the top one last
  for (int i = 0; i < 4; ++i) {
    const double y = 0.5 + 0.25 * outer[8][1] + i;
    l.boxes.push_back({0.0, y, 0.0, y, {{-2.0, -0.5}, {2.0, -0.5}, {2.0, 0.5}, {-2.0, 0.5}}});
  }
  return l;
}

// what one engine reports for one body at the end: position and velocity of its center
struct BodyEnd {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, omega = 0.0;
};

// how well a stack held, from the boxes' final states (same order as layout.boxes)
struct StackMetrics {
  double topDisplacement = 0.0;  // |p − p_rest| of the top box, m (the start, when touching)
  double topDrop = 0.0;          // y_rest − y of the top box, m: how far it sank (the arch's sag)
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
    m.topDrop = top.restY - end.back().y;
  }
  return m;
}

}  // namespace bench

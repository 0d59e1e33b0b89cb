#include "sim/describe/part_outline.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sim::describe {
using sim::core::Shape;
using sim::core::Vec2;
using namespace sim::core;

namespace {

using Interval = std::pair<double, double>;

// the parameters t in [0, 1] of a + t d inside the part grown by `grow` (Cyrus–Beck clipping
// against each edge's line for a polygon; the quadratic for a circle), or an empty interval
Interval inside(const ShapePart& part, const Vec2& a, const Vec2& d, double grow) {
  double lo = 0.0, hi = 1.0;
  if (part.shape.kind == ShapeKind::Circle) {
    const Vec2 f = a - part.pose.x;
    const double r = part.shape.radius + grow;
    const double qa = d.squaredNorm(), qb = 2.0 * f.dot(d), qc = f.squaredNorm() - r * r;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (!(qa > 0.0) || disc < 0.0) return {1.0, 0.0};
    const double root = std::sqrt(disc);
    return {std::max(lo, (-qb - root) / (2.0 * qa)), std::min(hi, (-qb + root) / (2.0 * qa))};
  }
  const std::vector<Vec2>& v = part.shape.vertices;
  for (size_t e = 0; e < v.size(); ++e) {
    const Vec2 n = part.pose.q.apply(part.shape.normals[e]), p = part.pose.toWorld(v[e]);
    // n·(a + t d − p) ≤ grow
    const double num = grow - n.dot(a - p), den = n.dot(d);
    if (den == 0.0) {
      if (num < 0.0) return {1.0, 0.0};
    } else if (den > 0.0) {
      hi = std::min(hi, num / den);
    } else {
      lo = std::max(lo, num / den);
    }
  }
  return {lo, hi};
}

// a part's boundary as segments in its body's coordinates
std::vector<OutlineSegment> boundary(const ShapePart& part, int circleSegments) {
  std::vector<OutlineSegment> out;
  if (part.shape.kind == ShapeKind::Circle) {
    const double r = part.shape.radius;
    for (int k = 0; k < circleSegments; ++k) {
      const double t0 = 2.0 * std::numbers::pi * k / circleSegments, t1 = 2.0 * std::numbers::pi * (k + 1) / circleSegments;
      out.push_back(
          {part.pose.toWorld({r * std::cos(t0), r * std::sin(t0)}), part.pose.toWorld({r * std::cos(t1), r * std::sin(t1)})});
    }
    return out;
  }
  const std::vector<Vec2>& v = part.shape.vertices;
  for (size_t e = 0; e < v.size(); ++e) out.push_back({part.pose.toWorld(v[e]), part.pose.toWorld(v[(e + 1) % v.size()])});
  return out;
}

}  // namespace

std::vector<OutlineSegment> partOutline(const Shape& shape, int circleSegments) {
  std::vector<OutlineSegment> out;
  const double grow = 1e-9 * std::max(boundingRadius(shape), 1e-12);
  for (size_t k = 0; k < shape.parts.size(); ++k)
    for (const OutlineSegment& s : boundary(shape.parts[k], circleSegments)) {
      // the runs of the segment outside every other part
      std::vector<Interval> kept{{0.0, 1.0}};
      const Vec2 d = s.b - s.a;
      for (size_t j = 0; j < shape.parts.size(); ++j) {
        if (j == k) continue;
        const auto [lo, hi] = inside(shape.parts[j], s.a, d, grow);
        if (!(lo < hi)) continue;
        std::vector<Interval> next;
        for (const auto& [from, to] : kept) {
          if (from < lo) next.push_back({from, std::min(to, lo)});
          if (to > hi) next.push_back({std::max(from, hi), to});
        }
        kept = std::move(next);
      }
      for (const auto& [from, to] : kept)
        if (to - from > 1e-9) out.push_back({s.a + from * d, s.a + to * d});
    }
  return out;
}

}  // namespace sim::describe

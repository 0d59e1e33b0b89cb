#include "render/frame/sat_axes.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace render::frame {

using sim::core::Vec2;

double edgeSeparation(const sim::core::Body& polygon, int edge, const sim::core::Body& other) {
  const Vec2 p = polygon.pose().toWorld(polygon.shape.vertices[edge]);
  const Vec2 n = polygon.q.apply(polygon.shape.normals[edge]);
  double least = std::numeric_limits<double>::infinity();
  for (const Vec2& v : other.shape.vertices) least = std::min(least, n.dot(other.pose().toWorld(v) - p));
  return least;
}

void describeCandidateAxes(const sim::world::World& world, int a, int b, int skipEdge, double labelOffset, sim::debug::DebugDraw& draw) {
  for (const int i : {a, b}) {
    const sim::core::Body &polygon = world.bodies[i], &other = world.bodies[i == a ? b : a];
    const std::vector<Vec2>& v = polygon.shape.vertices;
    for (int e = 0; e < static_cast<int>(v.size()); ++e) {
      if (i == a && e == skipEdge) continue;
      const Vec2 p = polygon.pose().toWorld(v[e]), q = polygon.pose().toWorld(v[(e + 1) % v.size()]);
      char text[32];
      std::snprintf(text, sizeof text, "%.3g m", edgeSeparation(polygon, e, other));
      const Vec2 outward = polygon.q.apply(polygon.shape.normals[e]);
      draw.text(0.5 * (p + q) - labelOffset * outward, text, {sim::debug::DrawRole::Label, i, 1.0});
    }
  }
}

}  // namespace render::frame

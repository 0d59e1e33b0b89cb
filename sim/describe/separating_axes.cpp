#include "sim/describe/separating_axes.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "sim/collision/collide.h"
#include "sim/core/settings.h"
#include "sim/describe/number_text.h"

namespace sim::describe {
using sim::core::Body;
using sim::core::Vec2;
using sim::debug_draw::DebugDraw;
using sim::debug_draw::DrawRole;
using sim::world::World;
using namespace sim::collision;
using namespace sim::core;
using namespace sim::world;

namespace {

// a separation written beside edge e of `polygon`, `labelOffset` inside it: the other polygon comes
// from outside, and would cover it
void labelEdge(const Body& polygon, int body, int e, const std::string& text, double labelOffset, DebugDraw& draw) {
  const std::vector<Vec2>& v = polygon.shape.vertices;
  const Vec2 p = polygon.pose().toWorld(v[e]), q = polygon.pose().toWorld(v[(e + 1) % v.size()]);
  const Vec2 outward = polygon.q().apply(polygon.shape.normals[e]);
  draw.text(0.5 * (p + q) - labelOffset * outward, text, {DrawRole::Label, body, 1.0});
}

// a separation in m as a slide writes it: 0 within the event method's touching tolerance of the
// scene (a gap of round-off, 5.84e-13, is touching), else three significant digits
std::string separationText(const World& world, double separation) {
  return numberText(separation, 3, sim::core::settings::kTouchingTolerance * world.sceneSize()) + " m";
}

// every edge of polygons `a` and `b` labeled with its separation, except edge `skipEdge` of `a`
// (the reference edge, labeled already)
void describeCandidateAxes(const World& world, int a, int b, int skipEdge, double labelOffset, DebugDraw& draw) {
  for (const int i : {a, b}) {
    const Body &polygon = world.bodies[i], &other = world.bodies[i == a ? b : a];
    for (int e = 0; e < static_cast<int>(polygon.shape.vertices.size()); ++e) {
      if (i == a && e == skipEdge) continue;
      labelEdge(polygon, i, e, separationText(world, edgeSeparation(polygon, e, other)), labelOffset, draw);
    }
  }
}

}  // namespace

double edgeSeparation(const Body& polygon, int edge, const Body& other) {
  const Vec2 p = polygon.pose().toWorld(polygon.shape.vertices[edge]);
  const Vec2 n = polygon.q().apply(polygon.shape.normals[edge]);
  double least = std::numeric_limits<double>::infinity();
  for (const Vec2& v : other.shape.vertices) least = std::min(least, n.dot(other.pose().toWorld(v) - p));
  return least;
}

void describeSeparatingAxes(const World& world, double maxGap, double labelOffset, DebugDraw& draw, bool everyAxis) {
  const auto& bodies = world.bodies;
  for (size_t i = 0; i < bodies.size(); ++i)
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      const Body &a = bodies[i], &b = bodies[j];
      if (a.shape.kind != ShapeKind::Polygon || b.shape.kind != ShapeKind::Polygon) continue;
      if (a.isStatic && b.isStatic) continue;
      const SatFeatures f = sat(a.shape, a.pose(), b.shape, b.pose());
      if (!f.valid || f.separation > maxGap) continue;
      // the notes' slide: the edge of one polygon whose separation is largest, and the vertex of
      // the other that is deepest below it
      const int refIndex = static_cast<int>(f.referenceOnA ? i : j), otherIndex = static_cast<int>(f.referenceOnA ? j : i);
      const Body &ref = bodies[refIndex], &other = bodies[otherIndex];
      const std::vector<Vec2>& v = ref.shape.vertices;
      const int e = f.referenceEdge;
      draw.segment(ref.pose().toWorld(v[e]), ref.pose().toWorld(v[(e + 1) % v.size()]), {DrawRole::ReferenceEdge, refIndex, 1.0});
      draw.point(other.pose().toWorld(other.shape.vertices[f.incidentVertex]), {DrawRole::IncidentVertex, otherIndex, 1.0});
      labelEdge(ref, refIndex, e, "separation " + separationText(world, f.separation), labelOffset, draw);
      if (everyAxis) describeCandidateAxes(world, refIndex, otherIndex, e, labelOffset, draw);
    }
}

}  // namespace sim::describe

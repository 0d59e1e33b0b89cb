#include "sim/debug/describe.h"

namespace sim::debug {
using namespace sim::core;
using namespace sim::world;

void describeBodies(const World& world, DebugDraw& draw, double opacity) {
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    const DrawStyle style{b.isStatic ? DrawRole::StaticBody : DrawRole::Body, static_cast<int>(i), opacity};
    const Pose pose = b.pose();
    switch (b.shape.kind) {
      case ShapeKind::Polygon: {
        std::vector<Vec2> v;
        v.reserve(b.shape.vertices.size());
        for (const Vec2& p : b.shape.vertices) v.push_back(pose.toWorld(p));
        draw.polygon(v, style);
        break;
      }
      case ShapeKind::Circle:
        draw.circle(b.x, b.shape.radius, style);
        draw.segment(b.x, pose.toWorld({b.shape.radius, 0.0}), {DrawRole::BodyAxis, static_cast<int>(i), opacity});
        break;
      case ShapeKind::Plane:
        draw.halfPlane(b.x, b.q.apply(b.shape.planeNormal), style);
        break;
    }
  }
}

}  // namespace sim::debug

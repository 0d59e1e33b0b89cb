#include "sim/describe/describe.h"

#include "sim/collision/compound.h"
#include "sim/describe/part_outline.h"

namespace sim::describe {
using namespace sim::debug_draw;
using namespace sim::world;
using namespace sim::collision;
using namespace sim::core;
using sim::collision::Manifold;

namespace {

// a spring's coils: this many zigzag points, and straight leads of this fraction at each end
constexpr int kSpringZigs = 12;
constexpr double kSpringLead = 0.12;

// a spring from a to b as a zigzag `amplitude` wide
void describeSpring(const Vec2& a, const Vec2& b, double amplitude, DebugDraw& draw) {
  const DrawStyle style{DrawRole::Spring, -1, 1.0};
  const Vec2 d = b - a;
  const double length = d.norm();
  if (!(length > 0.0)) return;
  const Vec2 side = Vec2(-d.y(), d.x()) / length * amplitude;
  // a straight lead in, the zigs alternating sides, a straight lead out
  Vec2 from = a + kSpringLead * d;
  draw.segment(a, from, style);
  for (int i = 0; i < kSpringZigs; ++i) {
    const double u = kSpringLead + (1.0 - 2.0 * kSpringLead) * (i + 0.5) / kSpringZigs;
    const Vec2 to = a + u * d + (i % 2 ? side : Vec2(-side));
    draw.segment(from, to, style);
    from = to;
  }
  const Vec2 leadOut = a + (1.0 - kSpringLead) * d;
  draw.segment(from, leadOut, style);
  draw.segment(leadOut, b, style);
}

// the normal as the notes draw it, from B into A; turned into B when A does not move (a floor)
Vec2 shownNormal(const World& world, int a, const Vec2& normal) { return world.bodies[a].isStatic ? Vec2(-normal) : normal; }

// a body made of parts as one body: its parts filled, then its outline, with no seam between parts
// that touch; a circle part's radius shows its turning
void describeParts(const Body& b, int index, double opacity, DebugDraw& draw) {
  const Pose pose = b.pose();
  for (const ShapePart& part : b.shape.parts) {
    const Pose p = sim::collision::partPose(pose, part);
    if (part.shape.kind == ShapeKind::Circle) {
      draw.circle(p.x, part.shape.radius, {DrawRole::BodyPart, index, opacity});
      continue;
    }
    std::vector<Vec2> v;
    for (const Vec2& q : part.shape.vertices) v.push_back(p.toWorld(q));
    draw.polygon(v, {DrawRole::BodyPart, index, opacity});
  }
  for (const OutlineSegment& s : partOutline(b.shape))
    draw.segment(pose.toWorld(s.a), pose.toWorld(s.b), {DrawRole::BodyEdge, index, opacity});
  for (const ShapePart& part : b.shape.parts)
    if (part.shape.kind == ShapeKind::Circle) {
      const Pose p = sim::collision::partPose(pose, part);
      draw.segment(p.x, p.toWorld({part.shape.radius, 0.0}), {DrawRole::BodyAxis, index, opacity});
    }
}

}  // namespace

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
      case ShapeKind::Plane: draw.halfPlane(b.x, b.q().apply(b.shape.planeNormal), style); break;
      case ShapeKind::Compound: describeParts(b, static_cast<int>(i), opacity, draw); break;
    }
  }
}

void contactMarks(const World& world, std::vector<ContactMark>& out) {
  auto mark = [&](const Contact& c) {
    const Manifold& m = c.manifold;
    const Vec2 n = shownNormal(world, c.a, m.normal);
    for (int k = 0; k < m.count; ++k) out.push_back({m.points[k].point, n});
  };
  for (const Contact& c : world.contacts) mark(c);
  // a sleeping pile still touches where it touched when it fell asleep (sim: {sleep: true})
  for (const std::vector<Contact>& island : world.sleepingContacts())
    for (const Contact& c : island) mark(c);
}

void describeContactMarks(const std::vector<ContactMark>& marks, double normalLength, DebugDraw& draw) {
  for (const ContactMark& m : marks) {
    draw.arrow(m.point, m.point + normalLength * m.normal, {DrawRole::ContactNormal, -1, 1.0});
    draw.point(m.point, {DrawRole::ContactPoint, -1, 1.0});
  }
}

void describeImpact(const World& world, const ImpactRecord& r, double impulseScale, double normalLength, DebugDraw& draw) {
  const Vec2 j = impulseScale * r.impulse * r.normal;
  if (!world.bodies[r.a].isStatic) draw.arrow(r.point, r.point + j, {DrawRole::Impulse, r.a, 1.0});
  if (!world.bodies[r.b].isStatic) draw.arrow(r.point, r.point - j, {DrawRole::Impulse, r.b, 1.0});
  draw.arrow(r.point, r.point + normalLength * shownNormal(world, r.a, r.normal), {DrawRole::ContactNormal, -1, 1.0});
  draw.point(r.point, {DrawRole::ContactPoint, -1, 1.0});
}

Arrow describeEventImpulse(const World& world, const ImpulseEvent& e, double impulseScale, DebugDraw& draw) {
  const Body& b = world.bodies[e.body];
  const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
  // the arrow ends where the impulse is applied, as a blow that strikes the body there
  const Arrow arrow{r - impulseScale * e.impulse, r};
  draw.arrow(arrow.tail, arrow.head, {DrawRole::Impulse, e.body, 1.0});
  return arrow;
}

void describeSprings(const World& world, double amplitude, DebugDraw& draw) {
  for (const Spring& sp : world.def().forces.springs) {
    const Vec2 a = world.bodies[sp.bodyA].pose().toWorld(sp.pointA);
    const bool anchored = sp.bodyB == kWorldAnchor;
    const Vec2 b = anchored ? sp.pointB : world.bodies[sp.bodyB].pose().toWorld(sp.pointB);
    describeSpring(a, b, amplitude, draw);
    if (anchored) draw.point(b, {DrawRole::StaticBody, -1, 1.0});
  }
}

}  // namespace sim::describe

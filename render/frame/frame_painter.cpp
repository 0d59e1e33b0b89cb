#include "render/frame/frame_painter.h"

#include <cstdio>

#include "render/draw/style.h"
#include "render/frame/sat_axes.h"
#include "sim/collision/collide.h"
#include "sim/debug/describe.h"

namespace render::frame {
using namespace render::draw;

namespace {

using sim::debug::DrawRole;

// a contact normal's arrow, as a fraction of the view's height: 58 px at 720p
constexpr double kNormalFraction = 0.08;

// a spring's coils: this many zigzag points, and straight leads of this fraction at each end
constexpr int kSpringZigs = 12;
constexpr double kSpringLead = 0.12;

// a spring from a to b as a zigzag `amplitude` wide, and a dot at a world anchor
void describeSpring(const Vec2& a, const Vec2& b, double amplitude, sim::debug::DebugDraw& draw) {
  const sim::debug::DrawStyle style{DrawRole::Spring, -1, 1.0};
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

}  // namespace

void describeContacts(const sim::world::World& world, double normalLength, sim::debug::DebugDraw& draw) {
  for (const sim::world::Contact& c : world.contacts) {
    const sim::collision::Manifold& m = c.manifold;
    // the normal from B into A as in the notes, turned into B when A does not move (a floor)
    const Vec2 n = world.bodies[c.a].isStatic ? Vec2(-m.normal) : m.normal;
    for (int k = 0; k < m.count; ++k) {
      const Vec2& p = m.points[k].point;
      draw.arrow(p, p + normalLength * n, {DrawRole::ContactNormal, -1, 1.0});
      draw.point(p, {DrawRole::ContactPoint, -1, 1.0});
    }
  }
}

void describeSeparatingAxes(const sim::world::World& world, double maxGap, double labelOffset, sim::debug::DebugDraw& draw,
                            bool everyAxis) {
  const auto& bodies = world.bodies;
  for (size_t i = 0; i < bodies.size(); ++i)
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      const sim::core::Body &a = bodies[i], &b = bodies[j];
      if (a.shape.kind != sim::core::ShapeKind::Polygon || b.shape.kind != sim::core::ShapeKind::Polygon) continue;
      if (a.isStatic && b.isStatic) continue;
      const sim::collision::SatFeatures f = sim::collision::sat(a.shape, a.pose(), b.shape, b.pose());
      if (!f.valid || f.separation > maxGap) continue;
      // the notes' slide: the edge of one polygon whose separation is largest, and the vertex of
      // the other that is deepest below it
      const int refIndex = static_cast<int>(f.referenceOnA ? i : j), otherIndex = static_cast<int>(f.referenceOnA ? j : i);
      const sim::core::Body &ref = bodies[refIndex], &other = bodies[otherIndex];
      const std::vector<Vec2>& v = ref.shape.vertices;
      const int e = f.referenceEdge;
      const Vec2 p = ref.pose().toWorld(v[e]), q = ref.pose().toWorld(v[(e + 1) % v.size()]);
      draw.segment(p, q, {DrawRole::ReferenceEdge, refIndex, 1.0});
      draw.point(other.pose().toWorld(other.shape.vertices[f.incidentVertex]), {DrawRole::IncidentVertex, otherIndex, 1.0});
      // the separation beside the edge, inside the reference polygon: the other one comes from
      // outside, and would cover it
      char text[64];
      std::snprintf(text, sizeof text, "separation %.3g m", f.separation);
      const Vec2 outward = ref.q.apply(ref.shape.normals[e]);
      draw.text(0.5 * (p + q) - labelOffset * outward, text, {DrawRole::Label, refIndex, 1.0});
      if (everyAxis) describeCandidateAxes(world, refIndex, otherIndex, e, labelOffset, draw);
    }
}

FramePainter::FramePainter(const sim::scene::SceneDef& def, const Camera& camera, const RunSurvey& survey,
                           const TextWidth& width)
    : def_(def),
      camera_(camera),
      impulseScale_(arrowScale(def.render.impulseScale, survey.maxImpulse, camera)),
      velocityScale_(arrowScale(def.render.velocityScale, survey.maxSpeed, camera)),
      arrows_(def, camera, survey, velocityScale_),
      panel_(def, camera, survey) {
  // the caption is the same in every frame: wrapped once, to the frame less an inset on each side
  const std::string caption = captionOf(def);
  const int size = fontSizeFor(def.render, camera.heightPx());
  const CaptionLayout layout = captionLayout(size);
  if (!caption.empty())
    captionLines_ = wrapLines(caption, camera.widthPx() - static_cast<int>(2 * layout.inset), layout.maxLines,
                              width ? width : estimatedWidth(size));
}

History::Options FramePainter::historyOptions() const {
  const sim::scene::RenderDef& r = def_.render;
  History::Options o;
  o.trails = r.trails;
  o.hold = r.contactHold;
  o.eventImpulses = r.impulses;
  o.impacts = r.contacts;
  o.impulseScale = impulseScale_;
  o.normalLength = kNormalFraction * camera_.worldHeight();
  o.points = arrows_.paths();
  if (r.overlays.impactValues)
    o.labels.emplace(fontSizeFor(r, camera_.heightPx()) * camera_.pixelSize(), impulseScale_, o.normalLength);
  if (r.contacts) {
    const double length = o.normalLength;
    o.contacts = [length](const sim::world::World& world, sim::debug::DebugDraw& draw) { describeContacts(world, length, draw); };
  }
  return o;
}

void FramePainter::paint(const sim::world::World& world, const History& history, const std::vector<DrawList>& ghosts,
                         sim::debug::DebugDraw& draw) const {
  const sim::scene::RenderDef& r = def_.render;
  const double px = camera_.pixelSize();
  // static bodies and planes at the back, so that everything that moves is drawn over them
  RoleFilter statics(draw, [](DrawRole role) { return role == DrawRole::StaticBody; });
  sim::debug::describeBodies(world, statics);
  // trails, points 1.5 px apart at most: smooth, and a few hundred segments for a long run
  if (r.trails) history.drawTrails(draw, 1.5 * px);
  for (const DrawList& ghost : ghosts) ghost.replay(draw);
  RoleFilter moving(draw, [](DrawRole role) { return role != DrawRole::StaticBody; });
  sim::debug::describeBodies(world, moving);
  if (r.springs)
    for (const sim::core::Spring& sp : world.forces.springs) {
      const Vec2 a = world.bodies[sp.bodyA].pose().toWorld(sp.pointA);
      const bool anchored = sp.bodyB == sim::core::kWorldAnchor;
      const Vec2 b = anchored ? sp.pointB : world.bodies[sp.bodyB].pose().toWorld(sp.pointB);
      // coils 2.5 line widths to each side: visible, and narrower than most bodies
      describeSpring(a, b, 2.5 * def_.render.lineWidth * px, draw);
      if (anchored) draw.point(b, {DrawRole::StaticBody, -1, 1.0});
    }
  history.drawAfterimages(world.time, draw);
  const double textSize = fontSizeFor(r, camera_.heightPx()) * px;
  // the overlay of every polygon pair closer than a tenth of the view (so, as they approach), its
  // label a line of text out from the edge
  if (r.sat || r.overlays.satAxes)
    describeSeparatingAxes(world, 0.1 * camera_.worldHeight(), textSize, draw, r.overlays.satAxes);
  if (r.velocities)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::core::Body& b = world.bodies[i];
      const Vec2 arrow = velocityScale_ * b.v;
      // a velocity shorter than a pixel has no arrow to show
      if (!b.isStatic && arrow.norm() > px) draw.arrow(b.x, b.x + arrow, {DrawRole::Velocity, static_cast<int>(i), 1.0});
    }
  arrows_.draw(world, history, draw);
  if (r.labels)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::core::Body& b = world.bodies[i];
      const std::string& label = def_.bodies[i].label;
      // a half-plane has no middle to write on
      const bool bounded = b.shape.kind == sim::core::ShapeKind::Polygon || b.shape.kind == sim::core::ShapeKind::Circle;
      if (!label.empty() && bounded) draw.text(b.x, label, {DrawRole::Label, static_cast<int>(i), 1.0});
    }
  if (r.time) {
    // the top-left corner, in from the edges by about half a line of text
    const double inset = 0.5 * textSize / px;
    draw.text(camera_.toWorld({inset, inset}), timeText(world.time), {DrawRole::Caption, -1, 1.0});
  }
  if (r.overlays.energy || r.overlays.momentum) panel_.draw(world, draw);
  paintTimingText(world.time, draw);
}

void FramePainter::paintTimingText(double t, sim::debug::DebugDraw& draw) const {
  const CaptionLayout layout = captionLayout(fontSizeFor(def_.render, camera_.heightPx()));
  const double inset = layout.inset, line = layout.line;
  const double factor = slowMotion_ ? slowMotion_(t) : 1.0;
  if (factor > 1.0)
    draw.text(camera_.toWorld({inset, inset + (def_.render.time ? line : 0.0)}), slowMotionText(factor),
              {DrawRole::Caption, -1, 1.0});
  const double bottom = camera_.heightPx() - inset;
  for (size_t i = 0; i < captionLines_.size(); ++i) {
    const double top = bottom - line * static_cast<double>(captionLines_.size() - i);
    draw.text(camera_.toWorld({inset, top}), captionLines_[i], {DrawRole::Caption, -1, 1.0});
  }
}

std::string FramePainter::slowMotionText(double factor) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "slow motion ×1/%g", factor);
  return buf;
}

std::string FramePainter::timeText(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t = %.3f s", t);
  return buf;
}

}  // namespace render::frame

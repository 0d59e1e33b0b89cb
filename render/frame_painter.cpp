#include "frame_painter.h"

#include <cstdio>

#include "describe.h"

namespace render {

namespace {

using sim::DrawRole;

// an automatic arrow scale: the largest value's arrow is this fraction of the view's height
constexpr double kArrowFraction = 1.0 / 6.0;

// a contact normal's arrow, as a fraction of the view's height: 58 px at 720p
constexpr double kNormalFraction = 0.08;

// an arrow scale: the scene's, or one that makes `largest` a sixth of the view
double arrowScale(double given, double largest, const Camera& camera) {
  if (given > 0.0) return given;
  return largest > 0.0 ? kArrowFraction * camera.worldHeight() / largest : 1.0;
}

bool isSAT(DrawRole r) { return r == DrawRole::ReferenceEdge || r == DrawRole::IncidentVertex; }

// a spring's coils: this many zigzag points, and straight leads of this fraction at each end
constexpr int kSpringZigs = 12;
constexpr double kSpringLead = 0.12;

// a spring from a to b as a zigzag `amplitude` wide, and a dot at a world anchor
void describeSpring(const Vec2& a, const Vec2& b, double amplitude, sim::DebugDraw& draw) {
  const sim::DrawStyle style{DrawRole::Spring, -1, 1.0};
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

void describeContacts(const sim::World&, sim::DebugDraw&) {
  // the collision code does not describe its contacts yet (sim::describeContacts will)
}

FramePainter::FramePainter(const sim::SceneDef& def, const Camera& camera, const RunSurvey& survey)
    : def_(def),
      camera_(camera),
      impulseScale_(arrowScale(def.render.impulseScale, survey.maxImpulse, camera)),
      velocityScale_(arrowScale(def.render.velocityScale, survey.maxSpeed, camera)) {}

History::Options FramePainter::historyOptions() const {
  const sim::RenderDef& r = def_.render;
  History::Options o;
  o.trails = r.trails;
  o.hold = r.contactHold;
  o.eventImpulses = r.impulses;
  o.impacts = r.contacts;
  o.impulseScale = impulseScale_;
  o.normalLength = kNormalFraction * camera_.worldHeight();
  if (r.contacts || r.sat) {
    const bool contacts = r.contacts, sat = r.sat;
    // contacts and the separating-axis overlay come from one description: keep what is asked for
    o.contacts = [contacts, sat](const sim::World& world, sim::DebugDraw& draw) {
      RoleFilter filter(draw, [=](DrawRole role) { return isSAT(role) ? sat : contacts; });
      describeContacts(world, filter);
    };
  }
  return o;
}

void FramePainter::paint(const sim::World& world, const History& history, const std::vector<DrawList>& ghosts,
                         sim::DebugDraw& draw) const {
  const sim::RenderDef& r = def_.render;
  const double px = camera_.pixelSize();
  // static bodies and planes at the back, so that everything that moves is drawn over them
  RoleFilter statics(draw, [](DrawRole role) { return role == DrawRole::StaticBody; });
  sim::describeBodies(world, statics);
  // trails, points 1.5 px apart at most: smooth, and a few hundred segments for a long run
  if (r.trails) history.drawTrails(draw, 1.5 * px);
  for (const DrawList& ghost : ghosts) ghost.replay(draw);
  RoleFilter moving(draw, [](DrawRole role) { return role != DrawRole::StaticBody; });
  sim::describeBodies(world, moving);
  if (r.springs)
    for (const sim::Spring& sp : world.forces.springs) {
      const Vec2 a = world.bodies[sp.bodyA].pose().toWorld(sp.pointA);
      const bool anchored = sp.bodyB == sim::kWorldAnchor;
      const Vec2 b = anchored ? sp.pointB : world.bodies[sp.bodyB].pose().toWorld(sp.pointB);
      // coils 2.5 line widths to each side: visible, and narrower than most bodies
      describeSpring(a, b, 2.5 * def_.render.lineWidth * px, draw);
      if (anchored) draw.point(b, {DrawRole::StaticBody, -1, 1.0});
    }
  history.drawAfterimages(world.time, draw);
  if (r.velocities)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::Body& b = world.bodies[i];
      const Vec2 arrow = velocityScale_ * b.v;
      // a velocity shorter than a pixel has no arrow to show
      if (!b.isStatic && arrow.norm() > px) draw.arrow(b.x, b.x + arrow, {DrawRole::Velocity, static_cast<int>(i), 1.0});
    }
  if (r.labels)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::Body& b = world.bodies[i];
      const std::string& label = def_.bodies[i].label;
      // a half-plane has no middle to write on
      const bool bounded = b.shape.kind == sim::ShapeKind::Polygon || b.shape.kind == sim::ShapeKind::Circle;
      if (!label.empty() && bounded) draw.text(b.x, label, {DrawRole::Label, static_cast<int>(i), 1.0});
    }
  if (r.time) {
    // the top-left corner, in from the edges by about half a line of text
    const double inset = 0.5 * std::max(11.0, camera_.heightPx() / 36.0);
    draw.text(camera_.toWorld({inset, inset}), timeText(world.time), {DrawRole::Caption, -1, 1.0});
  }
}

std::string FramePainter::timeText(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t = %.3f s", t);
  return buf;
}

}  // namespace render

#include "render/frame/frame_painter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <iostream>

#include "render/draw/text.h"

#include "render/draw/style.h"
#include "render/frame/impulse_beside.h"
#include "render/frame/kept_run.h"
#include "render/frame/overlay_key.h"
#include "render/frame/trace_overlay.h"
#include "render/frame/upcoming_events.h"
#include "render/scene/scene_style.h"
#include "sim/collision/collide.h"
#include "sim/describe/describe.h"
#include "sim/describe/separating_axes.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;
using namespace render::scene;

namespace {

// a contact normal's arrow, as a fraction of the view's height: 58 px at 720p
constexpr double kNormalFraction = 0.08;
// labels: auto writes every body's label in a scene of at most this many bodies
constexpr size_t kFewBodies = 20;
// contacts: auto draws normals and impulses while fewer contact points than this are on screen
constexpr size_t kManyContacts = 200;
// many contact points: a dot's radius as a fraction of the bodies' narrowest width on the frame,
// so that a box keeps most of its face (four dots of a resting pile sit on each box's corners)
constexpr double kManyDotFraction = 0.125;
// many contact points: dots under this radius (1.5 px across) are left out, a blur rather than a dot
constexpr double kLeastDotRadiusPx = 0.75;
// px between two points of a trail, drawn and kept: smooth, and a few hundred segments for a long run
constexpr double kTrailSpacingPx = 1.5;

// the contact points drawn into it that lie inside `view`, counted as they come (nothing kept)
class ContactsInView final : public Canvas {
 public:
  explicit ContactsInView(const Bounds& view) : view_(view) {}
  size_t count = 0;
  void polygon(const std::vector<Vec2>&, const Pen&) override {}
  void circle(const Vec2&, double, const Pen&) override {}
  void halfPlane(const Vec2&, const Vec2&, const Pen&) override {}
  void segment(const Vec2&, const Vec2&, const Pen&) override {}
  void point(const Vec2& p, const Pen& pen) override {
    count += pen.role == Role::ContactPoint && p.x() >= view_.min.x() && p.x() <= view_.max.x() && p.y() >= view_.min.y() &&
             p.y() <= view_.max.y();
  }
  void arrow(const Vec2&, const Vec2&, const Pen&) override {}
  void text(const Vec2&, const std::string&, const Pen&) override {}
  void label(const Vec2&, const Vec2&, const std::string&, const Pen&) override {}

 private:
  Bounds view_;
};

}  // namespace

FramePainter::FramePainter(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey, const TextWidth& width)
    : def_(def),
      camera_(camera),
      impulseScale_(arrowScale(def.render.impulseScale, survey.maxImpulse, camera)),
      velocityScale_(arrowScale(def.render.velocityScale, survey.maxSpeed, camera)),
      textWidth_(width),
      arrows_(def, camera, survey, velocityScale_),
      panel_(def, camera, survey),
      look_(afterimageLook()) {
  // the caption is the same in every frame: wrapped once, to the frame less an inset on each side
  const std::string caption = captionOf(def);
  const int size = fontSizeFor(def.render, camera.heightPx());
  const CaptionLayout layout = captionLayout(size);
  if (!caption.empty())
    captionLines_ = wrapLines(caption, camera.widthPx() - static_cast<int>(2 * layout.inset), layout.maxLines,
                              width ? width : estimatedWidth(size));
}

History::Options FramePainter::historyOptions() const {
  // what a kept run records, its trail points kept at the frame's spacing
  History::Options o = keptHistoryOptions(def_);
  o.trailSpacing = kTrailSpacingPx * camera_.pixelSize();
  return o;
}

History::Look FramePainter::afterimageLook() const {
  const render::scene::RenderDef& r = def_.render;
  History::Look look;
  look.impulseScale = impulseScale_;
  look.normalLength = kNormalFraction * camera_.worldHeight();
  if (r.overlays.impactValues)
    look.labels.emplace(fontSizeFor(r, camera_.heightPx()) * camera_.pixelSize(), impulseScale_, look.normalLength);
  return look;
}

void FramePainter::paint(const sim::world::World& world, const History& history, const std::vector<DrawList>& ghosts,
                         Canvas& target, std::vector<PlacedText>* placed) const {
  const render::scene::RenderDef& r = def_.render;
  LabelPlacer draw(target, camera_, fontSizeFor(r, camera_.heightPx()), textWidth_);
  const double px = camera_.pixelSize();
  // static bodies and planes at the back, so that everything that moves is drawn over them
  RoleFilter statics(draw, [](Role role) { return role == Role::StaticBody; });
  PhysicsDraw staticPhysics(statics);
  sim::describe::describeBodies(world, staticPhysics);
  // trails, points 1.5 px apart at most: smooth, and a few hundred segments for a long run
  if (r.trails) history.drawTrails(draw, kTrailSpacingPx * px);
  for (const DrawList& ghost : ghosts) ghost.replay(draw);
  RoleFilter moving(draw, [](Role role) { return role != Role::StaticBody; });
  PhysicsDraw movingPhysics(moving);
  sim::describe::describeBodies(world, movingPhysics);
  // what the overlays drew, for the key to those not labelled where they are
  OverlaysSeen seen(draw);
  PhysicsDraw physics(seen);
  // coils 2.5 line widths to each side: visible, and narrower than most bodies
  if (r.springs) sim::describe::describeSprings(world, 2.5 * lineWidthFor(def_.render, camera_.heightPx()) * px, physics);
  // impulses beside the normals they share a line with, so that both show
  ImpulseBeside beside(seen, impulseOffsetPx(lineWidthFor(r, camera_.heightPx())) * px);
  // contacts: dots and normals while few are on screen, else (contacts: auto) dots alone, which
  // still show where bodies touch without a thicket of arrows over them
  // counted first, then drawn (a copy of tens of thousands of calls made a frame of a 5,050-box
  // pyramid allocate and free each)
  ContactsInView onScreen(camera_.view());
  if (r.contactsAuto) history.drawAfterimages(world, look_, onScreen);
  if (r.contactsAuto && onScreen.count >= kManyContacts) {
    // dots scaled to the bodies they sit on, or none where they would cover them
    const double radius = manyDotRadiusPx(world);
    const bool showDots = radius >= kLeastDotRadiusPx;
    RoleFilter dots(beside, [showDots](Role role) {
      return role != Role::ContactNormal && role != Role::Impulse && (showDots || role != Role::ContactPoint);
    });
    target.manyPoints(radius);
    history.drawAfterimages(world, look_, dots);
    target.manyPoints(0.0);
  } else {
    history.drawAfterimages(world, look_, beside);
  }
  // a poll's frames show the impulses still to come, dashed, so that its question can be asked from
  // the picture (struck at the center, or at the end?)
  if (!r.poll.question.empty() && r.impulses)
    drawUpcomingEvents(world, impulseScale_, camera_, lineWidthFor(r, camera_.heightPx()), draw);
  const double textSize = fontSizeFor(r, camera_.heightPx()) * px;
  // the overlay of every polygon pair closer than a tenth of the view (so, as they approach), its
  // label a line of text out from the edge
  if (r.sat || r.overlays.satAxes)
    sim::describe::describeSeparatingAxes(world, 0.1 * camera_.worldHeight(), textSize, physics, r.overlays.satAxes);
  if (r.velocities)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::core::Body& b = world.bodies[i];
      const Vec2 arrow = velocityScale_ * b.v;
      // a velocity shorter than a pixel has no arrow to show
      if (!b.isStatic && arrow.norm() > px) draw.arrow(b.x, b.x + arrow, {Role::Velocity, static_cast<int>(i), 1.0});
    }
  // the centers of mass, over the bodies and their arrows' tails
  if (r.centers)
    for (size_t i = 0; i < world.bodies.size(); ++i)
      if (!world.bodies[i].isStatic) draw.point(world.bodies[i].x, {Role::CenterOfMass, static_cast<int>(i), 1.0});
  arrows_.draw(world, history, draw);
  // another run's bodies over ours, past the placer: the labels go where they would without them
  if (r.overlay) drawTraceOverlay(def_, *r.overlay, world, camera_, target);
  if (r.labels) paintLabels(world, draw);
  if (r.time) {
    // the top-left corner, in from the edges by about half a line of text
    const double inset = 0.5 * textSize / px;
    draw.text(camera_.toWorld({inset, inset}), timeText(world.time), {Role::Caption, -1, 1.0});
  }
  if (r.overlays.energy || r.overlays.momentum) panel_.draw(world, draw, textWidth_);
  // the key under the clock (and the slow-motion note, and the overlay's legend)
  if (r.key)
    drawOverlayKey(overlayKeyRows(seen, r.overlays.impactValues), camera_, fontSizeFor(r, camera_.heightPx()), keyFirstRow(r),
                   draw);
  paintTimingText(world.time, draw);
  draw.finish();
  dropped_.report(draw.dropped(), world.time);
  if (placed) *placed = draw.placed();
}

double FramePainter::manyDotRadiusPx(const sim::world::World& world) const {
  // the moving bodies' median narrowest width on the frame, px (a pile's bodies, not its ground)
  std::vector<double> widths;
  widths.reserve(world.bodies.size());
  for (const sim::core::Body& b : world.bodies) {
    if (b.isStatic) continue;
    if (b.shape.kind == sim::core::ShapeKind::Circle) widths.push_back(2.0 * b.shape.radius);
    if (b.shape.kind != sim::core::ShapeKind::Polygon || b.shape.vertices.empty()) continue;
    // a convex polygon's width: the least, over its edges, of its extent along the edge's normal
    const std::vector<Vec2>& v = b.shape.vertices;
    double least = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < v.size(); ++k) {
      const Vec2 e = v[(k + 1) % v.size()] - v[k];
      if (!(e.norm() > 0.0)) continue;
      const Vec2 n = Vec2(-e.y(), e.x()).normalized();
      double lo = n.dot(v[0]), hi = lo;
      for (const Vec2& q : v) lo = std::min(lo, n.dot(q)), hi = std::max(hi, n.dot(q));
      least = std::min(least, hi - lo);
    }
    if (std::isfinite(least)) widths.push_back(least);
  }
  // the usual dot's own radius (lineWidthFor: 2 px at 720p) when no moving body says otherwise
  const double usual = 2.2 * lineWidthFor(def_.render, camera_.heightPx());
  if (widths.empty()) return usual;
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  return std::min(usual, kManyDotFraction * widths[widths.size() / 2] / camera_.pixelSize());
}

namespace {

// whether a point in a convex shape's own coordinates lies inside it, whichever way its vertices wind
bool insideConvex(const sim::core::Shape& shape, const Vec2& local) {
  if (shape.kind == sim::core::ShapeKind::Circle) return local.norm() <= shape.radius;
  const std::vector<Vec2>& v = shape.vertices;
  double winding = 0.0;
  for (size_t k = 0; k < v.size(); ++k) winding += v[k].x() * v[(k + 1) % v.size()].y() - v[(k + 1) % v.size()].x() * v[k].y();
  for (size_t k = 0; k < v.size(); ++k) {
    const Vec2 e = v[(k + 1) % v.size()] - v[k];
    if (winding * (e.x() * (local.y() - v[k].y()) - e.y() * (local.x() - v[k].x())) < 0.0) return false;
  }
  return true;
}

// whether a point in a body's coordinates lies inside its shape (a body of parts: inside one of them)
bool insideShape(const sim::core::Shape& shape, const Vec2& local) {
  if (shape.kind != sim::core::ShapeKind::Compound) return insideConvex(shape, local);
  for (const sim::core::ShapePart& part : shape.parts)
    if (insideConvex(part.shape, part.pose.toBody(local))) return true;
  return false;
}

Vec2 labelAnchor(const sim::core::Body& b) {
  if (b.shape.kind != sim::core::ShapeKind::Compound) return b.x;
  // a body of parts: the middle of its largest part (its center of mass may lie off the body, as an
  // L-shaped block's does, or under its center-of-mass mark)
  const sim::core::ShapePart* largest = &b.shape.parts.front();
  for (const sim::core::ShapePart& part : b.shape.parts)
    if (sim::core::areaProperties(part.shape).area > sim::core::areaProperties(largest->shape).area) largest = &part;
  return b.pose().toWorld(largest->pose.x);
}

}  // namespace

bool FramePainter::labelFits(size_t index, const sim::core::Body& b, const std::string& label) const {
  // the label's box, centered on the body, in world units, at the frame's font size
  const int size = fontSizeFor(def_.render, camera_.heightPx());
  const double px = camera_.pixelSize();
  if (labelWidthsPx_.size() <= index) labelWidthsPx_.resize(index + 1, -1.0);
  double& widthPx = labelWidthsPx_[index];
  if (widthPx < 0.0) widthPx = textWidth_ ? textWidth_(label) : estimatedWidth(size)(label);
  const double halfWidth = 0.5 * widthPx * px;
  const double halfHeight = 0.5 * lineHeightPx(size) * px;
  const sim::core::Pose pose = b.pose();
  for (const Vec2& corner :
       {Vec2(-halfWidth, -halfHeight), Vec2(halfWidth, -halfHeight), Vec2(halfWidth, halfHeight), Vec2(-halfWidth, halfHeight)})
    if (!insideShape(b.shape, pose.toBody(labelAnchor(b) + corner))) return false;
  return true;
}

void FramePainter::paintLabels(const sim::world::World& world, LabelPlacer& draw) const {
  const render::scene::RenderDef& r = def_.render;
  // labels: auto writes every label of a small scene; in a larger one only those that fit inside
  // their body, and a label the scene did not name itself never moves far from its body (no leader)
  const bool few = world.bodies.size() <= kFewBodies;
  size_t unfit = 0;
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const sim::core::Body& b = world.bodies[i];
    const render::scene::BodyLook& look = r.bodies[i];
    // a half-plane has no middle to write on
    const bool bounded = b.shape.kind != sim::core::ShapeKind::Plane;
    if (look.label.empty() || !bounded) continue;
    const Pen pen{Role::Label, static_cast<int>(i), 1.0};
    if (!r.labelsAuto) {
      draw.label(labelAnchor(b), Vec2::Zero(), look.label, pen);
    } else if (few || labelFits(i, b, look.label)) {
      if (look.named) draw.label(labelAnchor(b), Vec2::Zero(), look.label, pen);
      else draw.labelNearby(labelAnchor(b), Vec2::Zero(), look.label, pen);
    } else {
      ++unfit;
    }
  }
  if (unfit > 0 && !unfitTold_) {
    unfitTold_ = true;
    std::cerr << "rigidreel: warning: " << unfit << " of " << world.bodies.size()
              << " body labels do not fit inside their bodies at this frame size and are not drawn "
                 "(labels: true draws them all)\n";
  }
}

void FramePainter::paintTimingText(double t, Canvas& draw) const {
  const CaptionLayout layout = captionLayout(fontSizeFor(def_.render, camera_.heightPx()));
  const double inset = layout.inset, line = layout.line;
  const double factor = slowMotion_ ? slowMotion_(t) : 1.0;
  if (factor > 1.0)
    draw.text(camera_.toWorld({inset, inset + (def_.render.time ? line : 0.0)}), slowMotionText(factor),
              {Role::Caption, -1, 1.0});
  const double bottom = camera_.heightPx() - inset;
  for (size_t i = 0; i < captionLines_.size(); ++i) {
    const double top = bottom - line * static_cast<double>(captionLines_.size() - i);
    draw.text(camera_.toWorld({inset, top}), captionLines_[i], {Role::Caption, -1, 1.0});
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

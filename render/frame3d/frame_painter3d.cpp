#include "render/frame3d/frame_painter3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "render/frame/frame_painter.h"
#include "render/frame3d/occlusion.h"
#include "render/draw/text.h"
#include "render/frame/quantity_text.h"
#include "render/scene/scene_style.h"

namespace render::frame3d {
using namespace render::draw;
using render::scene3d::Arrow3dDef;
using sim::core::Vec2;
using sim::world3d::Vec3;
using namespace sim::world3d;
using namespace render::draw3d;
using sim::world3d::Mat3;

namespace {

// the largest arrow of each kind is this fraction of the view's height at the camera's target: long enough
// to stick out of the bodies, short enough to stay clear of the text in the corners
constexpr double kArrowFraction = 1.0 / 4.0;
// a body's axes stick out of it: this many times its bounding radius long
constexpr double kAxesLength = 1.3;
// paths are drawn with points at least this many pixels apart: smooth, and a few hundred segments
constexpr double kPathSpacingPx = 1.5;
// a contact point hidden behind a body is drawn at this share of its opacity: there, but behind
constexpr double kBehindOpacity = 0.3;

double arrowScale(double given, double largest, const Camera3d& camera) {
  if (given > 0.0) return given;
  return largest > 0.0 ? kArrowFraction * camera.viewHeight() / largest : 1.0;
}

// a unit vector along v, or `fallback` when v has no length
Vec2 directionOr(const Vec2& v, const Vec2& fallback) {
  const double n = v.norm();
  return n > 0.0 ? Vec2(v / n) : fallback;
}

std::string defaultLabel(Arrow3dDef::Show show) {
  switch (show) {
    case Arrow3dDef::Show::Omega: return "ω";
    case Arrow3dDef::Show::AngularMomentum: return "L";
    case Arrow3dDef::Show::Velocity: return "v";
    case Arrow3dDef::Show::Path: return "r";
    default: return "";
  }
}

}  // namespace

FramePainter3d::FramePainter3d(const render::scene3d::Scene& def, const Camera3d& camera, const RunSurvey3d& survey,
                               const render::frame::TextWidth& width)
    : def_(def),
      camera_(camera),
      overlay_(overlayCamera(camera.widthPx(), camera.heightPx())),
      textWidth_(width),
      omegaScale_(arrowScale(def.space.omegaScale, survey.maxOmega, camera)),
      momentumScale_(arrowScale(def.space.angularMomentumScale, survey.maxAngularMomentum, camera)),
      velocityScale_(arrowScale(def.space.velocityScale, survey.maxSpeed, camera)),
      impulseScale_(arrowScale(0.0, survey.maxImpulse, camera)),
      // a patch twice as wide as the ball around everything the run covers
      planeMesh_(planeMesh(std::max(4.0 * survey.bounds.ball().radius, 1.0), 10)),
      planeCenter_(survey.bounds.ball().center),
      em_(render::scene::fontSizeFor(def.render, camera.heightPx())),
      lengthFloor_(render::frame::noiseFloor(survey.bounds.ball().radius + survey.bounds.ball().center.norm())),
      panel_(def, overlay_, survey) {
  for (const sim::scene3d::BodyDef& b : def.model.bodies) {
    const Mesh m = meshOf(b.shape, kLeastSegments);
    shapeKeys_.push_back(m.name);
    double radius = 0.0;
    for (const Vec3& p : m.positions) radius = std::max(radius, p.norm());
    if (b.shape.kind != sim::world3d::ShapeKind::Box)
      radius = b.shape.kind == sim::world3d::ShapeKind::Sphere ? b.shape.radius : b.shape.semiAxes.maxCoeff();
    radii_.push_back(radius);
  }
  // the caption is the same in every frame: wrapped once, to the frame less an inset on each side
  const std::string caption = render::frame::captionOf(def.render, def.model.description);
  const render::frame::CaptionLayout layout = render::frame::captionLayout(static_cast<int>(em_));
  if (!caption.empty())
    captionLines_ = render::frame::wrapLines(caption, camera.widthPx() - static_cast<int>(2 * layout.inset), layout.maxLines,
                                             width ? width : render::frame::estimatedWidth(static_cast<int>(em_)));
}

History3d::Options FramePainter3d::historyOptions() const {
  History3d::Options o = keptHistoryOptions(def_);
  // a pixel at the target's depth
  o.spacing = camera_.viewHeight() / camera_.heightPx();
  o.omegaSpacing = o.spacing / omegaScale_;
  return o;
}

std::optional<Vec2> FramePainter3d::screen(const Vec3& world) const {
  const Vec3 c = camera_.toCamera(world);
  if (!(c.z() > camera_.nearDepth())) return std::nullopt;
  return overlayPoint(camera_.pixelOf(c), camera_.heightPx());
}

void FramePainter3d::arrow(const Vec3& tail, const Vec3& head, const Pen& pen, const std::string& label, Canvas& draw) const {
  const std::optional<Vec2> t = screen(tail), h = screen(head);
  if (!t || !h) return;
  // an arrow under a pixel long has nothing to show, not even its direction
  if ((*h - *t).norm() >= 1.0) draw.arrow(*t, *h, pen);
  // beyond its head, where the frame's placer finds room (L and ω side by side never overprint)
  if (!label.empty()) draw.label(*h, directionOr(*h - *t, Vec2::UnitY()), label, {Role::Label, pen.body, 1.0});
}

void FramePainter3d::path(const std::vector<Vec3>& points, const Vec3& offset, const Pen& pen, Canvas& draw) const {
  std::optional<Vec2> last;
  for (size_t i = 0; i < points.size(); ++i) {
    const std::optional<Vec2> p = screen(offset + points[i]);
    if (!p) {
      last.reset();
      continue;
    }
    // points closer than the spacing merged, the newest always drawn to
    if (last && (*p - *last).norm() < kPathSpacingPx && i + 1 < points.size()) continue;
    if (last) draw.segment(*last, *p, pen);
    last = p;
  }
}

void FramePainter3d::paintArrows(const World& world, const History3d& history, Canvas& draw) const {
  size_t pointPaths = 0, omegaPaths = 0;
  for (size_t k = 0; k < def_.space.arrows.size(); ++k) {
    const Arrow3dDef& a = def_.space.arrows[k];
    const Body& b = world.bodies[a.body];
    const int color = a.color.empty() ? -1 : static_cast<int>(k);
    const std::string name = a.label.empty() ? defaultLabel(a.show) : a.label;
    // a component below the vector's noise floor (round-off of a turned vector: 1.19 × 10⁻¹⁴ beside 2) is 0
    auto labeled = [&](const Vec3& v, const char* unit) {
      return a.value ? render::frame::vectorText(name, v, unit, render::frame::noiseFloor(v.norm())) : name;
    };
    switch (a.show) {
      case Arrow3dDef::Show::Axes: {
        const Mat3 r = b.rotation();
        const double length = kAxesLength * boundingRadius(b.shape);
        const std::array<Role, 3> roles = {Role::AxisX, Role::AxisY, Role::AxisZ};
        const std::array<const char*, 3> names = {"x_b", "y_b", "z_b"};
        for (int i = 0; i < 3; ++i)
          arrow(b.x, b.x + length * r.col(i), {roles[i], a.body, 1.0, color}, a.label.empty() ? names[i] : a.label, draw);
        break;
      }
      case Arrow3dDef::Show::Omega:
        arrow(b.x, b.x + omegaScale_ * b.omega, {Role::AngularVelocity, a.body, 1.0, color}, labeled(b.omega, "rad/s"), draw);
        break;
      case Arrow3dDef::Show::AngularMomentum: {
        const Vec3 l = b.angularMomentum();
        arrow(b.x, b.x + momentumScale_ * l, {Role::AngularMomentum, a.body, 1.0, color}, labeled(l, "kg·m²/s"), draw);
        break;
      }
      case Arrow3dDef::Show::Velocity: {
        const Vec3 r = b.toWorld(a.at), v = b.pointVelocity(r);
        arrow(r, r + velocityScale_ * v, {Role::Velocity, a.body, 1.0, color}, labeled(v, "m/s"), draw);
        break;
      }
      case Arrow3dDef::Show::Path: {
        const std::vector<Vec3>& points = history.pointPath(pointPaths++);
        path(points, Vec3::Zero(), {Role::Path, a.body, 1.0, color}, draw);
        if (const std::optional<Vec2> p = screen(points.back())) {
          draw.point(*p, {Role::Path, a.body, 1.0, color});
          if (!name.empty()) draw.label(*p, Vec2::UnitY(), name, {Role::Label, a.body, 1.0});
        }
        break;
      }
      case Arrow3dDef::Show::OmegaPath: {
        // ω's tip over the run, drawn from the center now: the cone ω sweeps
        std::vector<Vec3> tips = history.omegaPath(omegaPaths++);
        for (Vec3& w : tips) w *= omegaScale_;
        path(tips, b.x, {Role::AngularVelocity, a.body, 0.6, color}, draw);
        break;
      }
      case Arrow3dDef::Show::State: break;  // text, with the time (paintText)
    }
  }
}

std::vector<std::string> FramePainter3d::stateText(const Body& b, double lengthFloor) {
  char q[160], norm[64];
  std::snprintf(q, sizeof q, "q = [%s, %s, %s, %s]", render::frame::signedNumber(b.q.w(), 3).c_str(),
                render::frame::signedNumber(b.q.x(), 3).c_str(), render::frame::signedNumber(b.q.y(), 3).c_str(),
                render::frame::signedNumber(b.q.z(), 3).c_str());
  std::snprintf(norm, sizeof norm, "|q| = %.6f", b.q.norm());
  return {render::frame::vectorText("x", b.x, "m", std::max(lengthFloor, render::frame::noiseFloor(b.x.norm()))), q, norm};
}

void FramePainter3d::paintText(const World& world, Canvas& draw) const {
  const render::frame::CaptionLayout layout = render::frame::captionLayout(static_cast<int>(em_));
  const double inset = layout.inset, line = layout.line;
  auto at = [&](double xPx, double yPx) { return overlay_.toWorld({xPx, yPx}); };
  const Pen caption{Role::Caption, -1, 1.0};
  double row = 0.0;
  if (def_.render.time) draw.text(at(inset, inset), render::frame::FramePainter::timeText(world.time), caption), row += 1.0;
  // a video's slow-motion note has its row under the time; the state text keeps its rows below it
  const double factor = slowMotion_ ? slowMotion_(world.time) : 1.0;
  if (factor > 1.0) draw.text(at(inset, inset + row * line), render::frame::FramePainter::slowMotionText(factor), caption);
  if (!def_.render.slowMotion.empty()) row += 1.0;
  for (const Arrow3dDef& a : def_.space.arrows) {
    if (a.show != Arrow3dDef::Show::State) continue;
    std::vector<std::string> lines = stateText(world.bodies[a.body], lengthFloor_);
    // several bodies: each block says whose
    if (world.bodies.size() > 1) {
      const std::string& label = def_.render.bodies[a.body].label;
      lines.insert(lines.begin(), (label.empty() ? def_.model.bodies[a.body].name : label) + ":");
    }
    for (const std::string& text : lines) draw.text(at(inset, inset + row * line), text, caption), row += 1.0;
  }
  const double bottom = camera_.heightPx() - inset;
  for (size_t i = 0; i < captionLines_.size(); ++i)
    draw.text(at(inset, bottom - line * static_cast<double>(captionLines_.size() - i)), captionLines_[i], caption);
}

void FramePainter3d::paintWorldAxes(Canvas& draw) const {
  // bottom right, above the caption's band: which way x, y and z point, the farthest drawn first
  const double band = captionLines_.empty() ? 0.0 : render::frame::captionLayout(static_cast<int>(em_)).band();
  const Vec2 origin = overlay_.toWorld({camera_.widthPx() - 3.0 * em_, camera_.heightPx() - band - 2.5 * em_});
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return camera_.basis()(2, a) > camera_.basis()(2, b); });
  const std::array<Role, 3> roles = {Role::AxisX, Role::AxisY, Role::AxisZ};
  const std::array<const char*, 3> names = {"x", "y", "z"};
  for (int k : order) {
    const Vec2 d = camera_.screenDirection(Vec3::Unit(k));
    const Vec2 up(d.x(), -d.y());  // the overlay's y is up
    const Vec2 head = origin + 1.6 * em_ * up;
    if ((head - origin).norm() >= 1.0) draw.arrow(origin, head, {roles[k], -1, 1.0});
    draw.text(origin + 2.3 * em_ * up, names[k], {Role::Label, -1, 1.0});
  }
}

const Mesh& FramePainter3d::meshFor(size_t i, const Body& b) const {
  // its radius on the frame at its depth (the largest level when it is at or behind the eye)
  const Vec3 c = camera_.toCamera(b.x);
  const double depth = c.z() - radii_[i];
  const int segments = depth > camera_.nearDepth() ? segmentsFor(radii_[i] * camera_.pixelsPerMeter(depth)) : 48;
  const std::pair<std::string, int> key(shapeKeys_[i],
                                        def_.model.bodies[i].shape.kind == sim::world3d::ShapeKind::Box ? 0 : segments);
  auto found = meshes_.find(key);
  if (found == meshes_.end()) found = meshes_.emplace(key, meshOf(def_.model.bodies[i].shape, segments)).first;
  return found->second;
}

void FramePainter3d::paintPlanes(const World& world, Canvas3d& canvas) const {
  for (const Plane& p : world.def().planes) {
    // the patch's z axis along the normal, centered below the run's middle
    const Quat turn = Quat::FromTwoVectors(Vec3::UnitZ(), p.normal);
    const Vec3 center = planeCenter_ - p.normal.dot(planeCenter_ - p.point) * p.normal;
    canvas.solid(planeMesh_, center, turn.toRotationMatrix(), {Role::StaticBody, -1, 1.0});
  }
}

void FramePainter3d::paintContacts(const World& world, Canvas& draw) const {
  // the normal arrows a fixed share of the frame long: they show a direction, not an amount
  const double normalPx = 2.5 * em_;
  const auto normalArrow = [&](const Vec3& point, const Vec3& normal, double opacity) {
    const std::optional<Vec2> p = screen(point), q = screen(point + 0.01 * normal);
    if (!p) return;
    // a point behind a body (a box's far corners on the floor) drawn faint, not as if in front
    if (hiddenByBodies(camera_.eye(), point, world.bodies, 2.0 * sim::core::settings::kLinearSlop)) opacity *= kBehindOpacity;
    draw.point(*p, {Role::ContactPoint, -1, opacity});
    if (q && (*q - *p).norm() > 1e-9) draw.arrow(*p, *p + normalPx * (*q - *p).normalized(), {Role::ContactNormal, -1, opacity});
  };
  for (const Contact3& c : world.findContacts(sim::core::settings::kTouchingTolerance * world.sceneSize() + 1e-6))
    for (int k = 0; k < c.count; ++k) normalArrow(c.points[k].point, c.normal, 1.0);
  const double hold = def_.render.contactHold;
  for (const ImpactRecord3& r : world.impacts) {
    if (!(r.t <= world.time && world.time - r.t <= hold)) continue;
    const double fade = hold > 0.0 ? 1.0 - (world.time - r.t) / hold : 1.0;
    normalArrow(r.point, r.normal, fade);
    // the impulse on A, ending at the point (as 2D draws an event's impulse)
    const Vec3 j = r.impulse * r.normal + r.tangentImpulse;
    arrow(r.point - impulseScale_ * j, r.point, {Role::Impulse, r.a, fade}, "", draw);
  }
}

void FramePainter3d::paint(const World& world, const History3d& history, Canvas3d& canvas) const {
  const render::scene::RenderDef& r = def_.render;
  paintPlanes(world, canvas);
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    canvas.solid(meshFor(i, b), b.x, b.rotation(), {Role::Body, static_cast<int>(i), 1.0});
  }
  // every text through one placer, as a 2D frame's, so that no two overlap
  render::frame::LabelPlacer draw(canvas.overlay(), overlay_, static_cast<int>(em_), textWidth_);
  paintContacts(world, draw);
  if (r.trails)
    for (size_t i = 0; i < world.bodies.size(); ++i)
      path(history.trail(i), Vec3::Zero(), {Role::Trail, static_cast<int>(i), 1.0}, draw);
  if (r.springs)
    for (const Spring& sp : world.def().forces.springs) {
      const Vec3 a = world.bodies[sp.bodyA].toWorld(sp.pointA);
      const Vec3 b = sp.bodyB == sim::core::kWorldAnchor ? sp.pointB : world.bodies[sp.bodyB].toWorld(sp.pointB);
      const std::optional<Vec2> pa = screen(a), pb = screen(b);
      if (pa && pb) draw.segment(*pa, *pb, {Role::Spring, -1, 1.0});
      if (pb && sp.bodyB == sim::core::kWorldAnchor) draw.point(*pb, {Role::Spring, -1, 1.0});
    }
  paintArrows(world, history, draw);
  if (r.labels)
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const Body& b = world.bodies[i];
      const std::string& label = r.bodies[i].label;
      const Vec3 c = camera_.toCamera(b.x);
      if (label.empty() || !(c.z() > camera_.nearDepth())) continue;
      // below the body, clear of the arrows from its center
      const double radius = boundingRadius(b.shape) * camera_.pixelsPerMeter(c.z());
      const Vec2 below = overlayPoint(camera_.pixelOf(c), camera_.heightPx()) - Vec2(0.0, radius + 0.8 * em_);
      draw.label(below, Vec2::Zero(), label, {Role::Label, static_cast<int>(i), 1.0});
    }
  if (def_.space.worldAxes) paintWorldAxes(draw);
  panel_.draw(world, draw);
  paintText(world, draw);
  draw.finish();
  dropped_.report(draw.dropped(), world.time);
}

}  // namespace render::frame3d

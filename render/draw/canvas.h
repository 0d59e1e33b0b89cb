// The renderer's drawing interface: the simulator's (sim::debug_draw::DebugDraw) with the renderer's
// roles. GlCanvas draws it with OpenGL; DrawList records it for tests and for afterimages. World
// coordinates, y up.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "render/draw/roles.h"
#include "sim/core/math.h"

namespace render::draw {

class Canvas {
 public:
  virtual ~Canvas() = default;
  // a closed convex polygon
  virtual void polygon(const std::vector<sim::core::Vec2>& vertices, const Pen& pen) = 0;
  virtual void circle(const sim::core::Vec2& center, double radius, const Pen& pen) = 0;
  // the half-plane {r : n·(r − point) ≤ 0}, filled out to the edges of the view
  virtual void halfPlane(const sim::core::Vec2& point, const sim::core::Vec2& normal, const Pen& pen) = 0;
  virtual void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& pen) = 0;
  virtual void point(const sim::core::Vec2& p, const Pen& pen) = 0;
  virtual void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const Pen& pen) = 0;
  // text exactly there: a Label centered on `at`, a Caption (fixed to the frame) with its top-left corner there
  virtual void text(const sim::core::Vec2& at, const std::string& text, const Pen& pen) = 0;
  // a label of the point `anchor` (what it names: a body's center, an arrow's head): centered on it
  // when `direction` is zero, else just beyond it along the unit `direction`, clear of it. A frame's
  // labels go through render::frame::LabelPlacer, which may move them to a free spot; any other
  // canvas draws them where they prefer to be
  virtual void label(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text,
                     const Pen& pen) = 0;
  // the points that follow are many (a frame of hundreds of contacts): a canvas may draw them
  // coarser, for speed, and a contact point as a plain dot `dotRadiusPx` across its radius, scaled
  // to the bodies it sits on, until told otherwise (0: each drawn as usual)
  virtual void manyPoints(double dotRadiusPx) { (void)dotRadiusPx; }
};

// the center of a label's box, half-extents `halfWidth` × `halfHeight`, beyond `anchor` along the
// unit `direction` with `gap` between the anchor and the box (its support distance along the
// direction plus the gap), or on the anchor when the direction is zero; any one unit throughout
inline sim::core::Vec2 labelCenter(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, double halfWidth,
                                   double halfHeight, double gap) {
  if (direction.isZero()) return anchor;
  const double reach = std::abs(direction.x()) * halfWidth + std::abs(direction.y()) * halfHeight;
  return anchor + direction * (reach + gap);
}

// the simulator's drawing calls onto a canvas, each role as its row of the table (Box2D's
// b2DebugDraw, implemented by the application)
class PhysicsDraw final : public sim::debug_draw::DebugDraw {
 public:
  explicit PhysicsDraw(Canvas& canvas) : canvas_(canvas) {}
  void polygon(const std::vector<sim::core::Vec2>& v, const sim::debug_draw::DrawStyle& s) override {
    canvas_.polygon(v, pen(s));
  }
  void circle(const sim::core::Vec2& c, double r, const sim::debug_draw::DrawStyle& s) override { canvas_.circle(c, r, pen(s)); }
  void halfPlane(const sim::core::Vec2& p, const sim::core::Vec2& n, const sim::debug_draw::DrawStyle& s) override {
    canvas_.halfPlane(p, n, pen(s));
  }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const sim::debug_draw::DrawStyle& s) override {
    canvas_.segment(a, b, pen(s));
  }
  void point(const sim::core::Vec2& p, const sim::debug_draw::DrawStyle& s) override { canvas_.point(p, pen(s)); }
  void arrow(const sim::core::Vec2& t, const sim::core::Vec2& h, const sim::debug_draw::DrawStyle& s) override {
    canvas_.arrow(t, h, pen(s));
  }
  // the simulator's text is a label written where it names (a separation inside its edge)
  void text(const sim::core::Vec2& at, const std::string& t, const sim::debug_draw::DrawStyle& s) override {
    canvas_.label(at, sim::core::Vec2::Zero(), t, pen(s));
  }

 private:
  static Pen pen(const sim::debug_draw::DrawStyle& s) { return {fromPhysics(s.role), s.body, s.opacity}; }
  Canvas& canvas_;
};

// every call into `target` whose role `keep` accepts (e.g. static bodies first)
template <class Keep>
class RoleFilter final : public Canvas {
 public:
  RoleFilter(Canvas& target, Keep keep) : target_(target), keep_(keep) {}
  void polygon(const std::vector<sim::core::Vec2>& v, const Pen& p) override {
    if (keep_(p.role)) target_.polygon(v, p);
  }
  void circle(const sim::core::Vec2& c, double r, const Pen& p) override {
    if (keep_(p.role)) target_.circle(c, r, p);
  }
  void halfPlane(const sim::core::Vec2& q, const sim::core::Vec2& n, const Pen& p) override {
    if (keep_(p.role)) target_.halfPlane(q, n, p);
  }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& p) override {
    if (keep_(p.role)) target_.segment(a, b, p);
  }
  void point(const sim::core::Vec2& q, const Pen& p) override {
    if (keep_(p.role)) target_.point(q, p);
  }
  void arrow(const sim::core::Vec2& t, const sim::core::Vec2& h, const Pen& p) override {
    if (keep_(p.role)) target_.arrow(t, h, p);
  }
  void text(const sim::core::Vec2& at, const std::string& t, const Pen& p) override {
    if (keep_(p.role)) target_.text(at, t, p);
  }
  void label(const sim::core::Vec2& a, const sim::core::Vec2& d, const std::string& t, const Pen& p) override {
    if (keep_(p.role)) target_.label(a, d, t, p);
  }

 private:
  Canvas& target_;
  Keep keep_;
};

// every call passed on to `target`, its pen's opacity times `opacity`: what DrawList::replay(target,
// opacity) draws of the calls recorded, without recording them (a history's fading afterimages)
class Faded final : public Canvas {
 public:
  Faded(Canvas& target, double opacity) : target_(target), opacity_(opacity) {}
  void polygon(const std::vector<sim::core::Vec2>& v, const Pen& p) override { target_.polygon(v, faded(p)); }
  void circle(const sim::core::Vec2& c, double r, const Pen& p) override { target_.circle(c, r, faded(p)); }
  void halfPlane(const sim::core::Vec2& q, const sim::core::Vec2& n, const Pen& p) override { target_.halfPlane(q, n, faded(p)); }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& p) override { target_.segment(a, b, faded(p)); }
  void point(const sim::core::Vec2& q, const Pen& p) override { target_.point(q, faded(p)); }
  void arrow(const sim::core::Vec2& t, const sim::core::Vec2& h, const Pen& p) override { target_.arrow(t, h, faded(p)); }
  void text(const sim::core::Vec2& at, const std::string& t, const Pen& p) override { target_.text(at, t, faded(p)); }
  void label(const sim::core::Vec2& a, const sim::core::Vec2& d, const std::string& t, const Pen& p) override {
    target_.label(a, d, t, faded(p));
  }

 private:
  Pen faded(Pen p) const {
    p.opacity *= opacity_;
    return p;
  }
  Canvas& target_;
  double opacity_;
};

// every call into both `first` and `second` (a frame drawn and its draw list recorded at once)
class BothCanvases final : public Canvas {
 public:
  BothCanvases(Canvas& first, Canvas& second) : first_(first), second_(second) {}
  void polygon(const std::vector<sim::core::Vec2>& v, const Pen& p) override { first_.polygon(v, p), second_.polygon(v, p); }
  void circle(const sim::core::Vec2& c, double r, const Pen& p) override { first_.circle(c, r, p), second_.circle(c, r, p); }
  void halfPlane(const sim::core::Vec2& q, const sim::core::Vec2& n, const Pen& p) override {
    first_.halfPlane(q, n, p), second_.halfPlane(q, n, p);
  }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& p) override {
    first_.segment(a, b, p), second_.segment(a, b, p);
  }
  void point(const sim::core::Vec2& q, const Pen& p) override { first_.point(q, p), second_.point(q, p); }
  void arrow(const sim::core::Vec2& t, const sim::core::Vec2& h, const Pen& p) override {
    first_.arrow(t, h, p), second_.arrow(t, h, p);
  }
  void text(const sim::core::Vec2& at, const std::string& t, const Pen& p) override {
    first_.text(at, t, p), second_.text(at, t, p);
  }
  void label(const sim::core::Vec2& a, const sim::core::Vec2& d, const std::string& t, const Pen& p) override {
    first_.label(a, d, t, p), second_.label(a, d, t, p);
  }
  void manyPoints(double dotRadiusPx) override { first_.manyPoints(dotRadiusPx), second_.manyPoints(dotRadiusPx); }

 private:
  Canvas& first_;
  Canvas& second_;
};

}  // namespace render::draw

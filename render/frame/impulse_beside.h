// Impulse arrows drawn beside the normal they lie on: at an impact the normal n̂ and the impulse
// γ n̂ start at the same contact point along the same line, so the impulse, drawn over it, hid the
// normal. Every Impulse arrow is moved sideways (to its left) by a fixed number of pixels, clear of
// a normal's stroke; everything else passes straight through.
#pragma once

#include "render/draw/canvas.h"

namespace render::frame {
using render::draw::Canvas;
using render::draw::Pen;
using sim::core::Vec2;

class ImpulseBeside final : public Canvas {
 public:
  // `offset`: how far the impulse's center line moves, world units
  ImpulseBeside(Canvas& target, double offset) : target_(target), offset_(offset) {}
  void polygon(const std::vector<Vec2>& v, const Pen& p) override { target_.polygon(v, p); }
  void circle(const Vec2& c, double r, const Pen& p) override { target_.circle(c, r, p); }
  void halfPlane(const Vec2& q, const Vec2& n, const Pen& p) override { target_.halfPlane(q, n, p); }
  void segment(const Vec2& a, const Vec2& b, const Pen& p) override { target_.segment(a, b, p); }
  void point(const Vec2& q, const Pen& p) override { target_.point(q, p); }
  void arrow(const Vec2& tail, const Vec2& head, const Pen& p) override;
  void text(const Vec2& at, const std::string& t, const Pen& p) override { target_.text(at, t, p); }
  void label(const Vec2& a, const Vec2& d, const std::string& t, const Pen& p) override { target_.label(a, d, t, p); }

 private:
  Canvas& target_;
  double offset_;
};

// the offset for strokes `lineWidth` px wide: a normal's stroke (1 line width), a gap of a line width
// and a half, half the impulse's (1.5 line widths), center to center
inline double impulseOffsetPx(double lineWidth) { return 2.0 * lineWidth; }

}  // namespace render::frame

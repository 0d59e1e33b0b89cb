// Impulse arrows drawn beside the normal they lie on: at an impact the normal n̂ and the impulse
// γ n̂ start at the same contact point along the same line, so the impulse, drawn over it, hid the
// normal. Every Impulse arrow is moved sideways (to its left) by a fixed number of pixels, clear of
// a normal's stroke; everything else passes straight through.
#pragma once

#include "render/draw/canvas.h"

namespace render::frame {

class ImpulseBeside final : public render::draw::Canvas {
 public:
  // `offset`: how far the impulse's center line moves, world units
  ImpulseBeside(render::draw::Canvas& target, double offset) : target_(target), offset_(offset) {}
  void polygon(const std::vector<sim::core::Vec2>& v, const render::draw::Pen& p) override { target_.polygon(v, p); }
  void circle(const sim::core::Vec2& c, double r, const render::draw::Pen& p) override { target_.circle(c, r, p); }
  void halfPlane(const sim::core::Vec2& q, const sim::core::Vec2& n, const render::draw::Pen& p) override {
    target_.halfPlane(q, n, p);
  }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const render::draw::Pen& p) override {
    target_.segment(a, b, p);
  }
  void point(const sim::core::Vec2& q, const render::draw::Pen& p) override { target_.point(q, p); }
  void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const render::draw::Pen& p) override;
  void text(const sim::core::Vec2& at, const std::string& t, const render::draw::Pen& p) override { target_.text(at, t, p); }
  void label(const sim::core::Vec2& a, const sim::core::Vec2& d, const std::string& t, const render::draw::Pen& p) override {
    target_.label(a, d, t, p);
  }

 private:
  render::draw::Canvas& target_;
  double offset_;
};

// the offset for strokes `lineWidth` px wide: a normal's stroke (1 line width), a gap of a line width
// and a half, half the impulse's (1.5 line widths), center to center
inline double impulseOffsetPx(double lineWidth) { return 2.0 * lineWidth; }

}  // namespace render::frame

// A DebugDraw that records its calls instead of drawing them: for tests, the middle level of the
// three regression levels (state hash, draw list, pixels) as text lines; for the renderer, a piece
// of a frame kept to be drawn again later (a contact that stays on screen, a strobe ghost).
#pragma once

#include <string>
#include <vector>

#include "sim/debug/debug_draw.h"

namespace render::draw {

using sim::core::Vec2;

// the role's name as written in draw lists, e.g. "ContactPoint"
const char* roleName(sim::debug::DrawRole role);

class DrawList : public sim::debug::DebugDraw {
 public:
  enum class Kind { Polygon, Circle, HalfPlane, Segment, Point, Arrow, Text };
  struct Call {
    Kind kind;
    std::vector<Vec2> points;  // vertices; center; point and normal; a and b; point; tail and head; at
    double radius = 0.0;
    std::string text;
    sim::debug::DrawStyle style;
  };

  void polygon(const std::vector<Vec2>& vertices, const sim::debug::DrawStyle& style) override;
  void circle(const Vec2& center, double radius, const sim::debug::DrawStyle& style) override;
  void halfPlane(const Vec2& point, const Vec2& normal, const sim::debug::DrawStyle& style) override;
  void segment(const Vec2& a, const Vec2& b, const sim::debug::DrawStyle& style) override;
  void point(const Vec2& p, const sim::debug::DrawStyle& style) override;
  void arrow(const Vec2& tail, const Vec2& head, const sim::debug::DrawStyle& style) override;
  void text(const Vec2& at, const std::string& text, const sim::debug::DrawStyle& style) override;

  const std::vector<Call>& calls() const { return calls_; }
  bool empty() const { return calls_.empty(); }
  void clear() { calls_.clear(); }
  // the calls again, into `target`, with every opacity multiplied by `opacity`
  void replay(sim::debug::DebugDraw& target, double opacity = 1.0) const;
  // one line per call, numbers to 6 significant digits, e.g.
  //   polygon Body#0 (-0.1,-2) (0.1,-2) (0.1,2) (-0.1,2)
  //   arrow Impulse@0.5 (0,1) -> (1,1)
  //   arrow Velocity#0~2 (0,0) -> (1,0)   (~2: the color of teaching arrow 2)
  std::vector<std::string> lines() const;
  // the lines joined, each ending in a newline
  std::string toText() const;

 private:
  std::vector<Call> calls_;
};

// every call of `source` into `target` whose role `keep` accepts (e.g. static bodies first)
template <class Keep>
class RoleFilter : public sim::debug::DebugDraw {
 public:
  RoleFilter(sim::debug::DebugDraw& target, Keep keep) : target_(target), keep_(keep) {}
  void polygon(const std::vector<Vec2>& v, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.polygon(v, s); }
  void circle(const Vec2& c, double r, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.circle(c, r, s); }
  void halfPlane(const Vec2& p, const Vec2& n, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.halfPlane(p, n, s); }
  void segment(const Vec2& a, const Vec2& b, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.segment(a, b, s); }
  void point(const Vec2& p, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.point(p, s); }
  void arrow(const Vec2& t, const Vec2& h, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.arrow(t, h, s); }
  void text(const Vec2& at, const std::string& t, const sim::debug::DrawStyle& s) override { if (keep_(s.role)) target_.text(at, t, s); }

 private:
  sim::debug::DebugDraw& target_;
  Keep keep_;
};

}  // namespace render::draw

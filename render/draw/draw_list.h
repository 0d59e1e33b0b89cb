// A DebugDraw that records its calls instead of drawing them: for tests, the middle level of the
// three regression levels (state hash, draw list, pixels) as text lines; for the renderer, a piece
// of a frame kept to be drawn again later (a contact that stays on screen, a strobe ghost).
#pragma once

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/draw/canvas.h"

namespace render::draw {

// a call's points: one or two held in place (a point, an arrow: no allocation, so that recording a
// pile's 20,000 contacts a step costs no malloc each), a polygon's vertices in a vector
class CallPoints {
 public:
  CallPoints(std::initializer_list<sim::core::Vec2> points) : count_(points.size()) {
    if (count_ > 2) {
      vertices_.assign(points.begin(), points.end());
      return;
    }
    std::copy(points.begin(), points.end(), held_);
  }
  explicit CallPoints(const std::vector<sim::core::Vec2>& vertices) : count_(vertices.size()), vertices_(vertices) {
    polygon_ = true;
  }
  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const sim::core::Vec2* begin() const { return stored() ? vertices_.data() : held_; }
  const sim::core::Vec2* end() const { return begin() + count_; }
  const sim::core::Vec2& operator[](size_t i) const { return begin()[i]; }
  const sim::core::Vec2& at(size_t i) const {
    if (i >= count_) throw std::out_of_range("CallPoints::at");
    return begin()[i];
  }
  // a polygon's vertices, as Canvas::polygon takes them
  const std::vector<sim::core::Vec2>& vertices() const { return vertices_; }

 private:
  bool stored() const { return polygon_ || count_ > 2; }
  size_t count_ = 0;
  bool polygon_ = false;
  sim::core::Vec2 held_[2];
  std::vector<sim::core::Vec2> vertices_;
};

// a pen as a draw-list line writes it: its role, then #body, @opacity and ~arrow colour where set,
// e.g. "Velocity#0~2"
std::string penName(const Pen& pen);

class DrawList final : public Canvas {
 public:
  enum class Kind { Polygon, Circle, HalfPlane, Segment, Point, Arrow, Text, Label };
  struct Call {
    Kind kind;
    CallPoints points;  // vertices; center; point and normal; a and b; point; tail and head; at; anchor and direction
    double radius = 0.0;
    std::string text;
    Pen style;
  };

  void polygon(const std::vector<sim::core::Vec2>& vertices, const Pen& style) override;
  void circle(const sim::core::Vec2& center, double radius, const Pen& style) override;
  void halfPlane(const sim::core::Vec2& point, const sim::core::Vec2& normal, const Pen& style) override;
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& style) override;
  void point(const sim::core::Vec2& p, const Pen& style) override;
  void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const Pen& style) override;
  void text(const sim::core::Vec2& at, const std::string& text, const Pen& style) override;
  void label(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text, const Pen& style) override;

  // "polygon", "circle", "halfplane", "segment", "point", "arrow", "text", "label"
  static const char* kindName(Kind kind);

  const std::vector<Call>& calls() const { return calls_; }
  bool empty() const { return calls_.empty(); }
  void clear() { calls_.clear(); }
  // the calls again, into `target`, with every opacity multiplied by `opacity`
  void replay(Canvas& target, double opacity = 1.0) const;
  // one line per call, numbers to 6 significant digits, e.g.
  //   polygon Body#0 (-0.1,-2) (0.1,-2) (0.1,2) (-0.1,2)
  //   arrow Impulse@0.5 (0,1) -> (1,1)
  //   arrow Velocity#0~2 (0,0) -> (1,0)   (~2: the color of teaching arrow 2)
  //   label Label#0 (0,1) beyond (0,1) "v"  (a label not yet placed)
  std::vector<std::string> lines() const;
  // the lines joined, each ending in a newline
  std::string toText() const;

 private:
  std::vector<Call> calls_;
};

}  // namespace render::draw

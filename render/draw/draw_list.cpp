#include "render/draw/draw_list.h"

#include <cmath>
#include <cstdio>

namespace render::draw {

using sim::core::Vec2;
namespace {

// 6 significant digits: what a picture can show, and stable under last-digit round-off; round-off
// around zero (1e-17 from a rotation) written as 0
std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::abs(x) < 1e-12 ? 0.0 : x);
  return buf;
}

std::string coordinates(const Vec2& p) {
  std::string s = "(";
  s.append(number(p.x())).append(",").append(number(p.y())).append(")");
  return s;
}

}  // namespace

std::string penName(const Pen& s) {
  std::string out(info(s.role).name);
  if (s.body >= 0) out.append("#").append(std::to_string(s.body));
  if (s.opacity != 1.0) out.append("@").append(number(s.opacity));
  if (s.color >= 0) out.append("~").append(std::to_string(s.color));
  return out;
}

const char* DrawList::kindName(Kind k) {
  switch (k) {
    case Kind::Polygon: return "polygon";
    case Kind::Circle: return "circle";
    case Kind::HalfPlane: return "halfplane";
    case Kind::Segment: return "segment";
    case Kind::Point: return "point";
    case Kind::Arrow: return "arrow";
    case Kind::Text: return "text";
    case Kind::Label: return "label";
  }
  return "?";
}

void DrawList::polygon(const std::vector<Vec2>& vertices, const Pen& style) {
  calls_.push_back({Kind::Polygon, CallPoints(vertices), 0.0, {}, style});
}
void DrawList::circle(const Vec2& center, double radius, const Pen& style) {
  calls_.push_back({Kind::Circle, {center}, radius, {}, style});
}
void DrawList::halfPlane(const Vec2& p, const Vec2& normal, const Pen& style) {
  calls_.push_back({Kind::HalfPlane, {p, normal}, 0.0, {}, style});
}
void DrawList::segment(const Vec2& a, const Vec2& b, const Pen& style) {
  calls_.push_back({Kind::Segment, {a, b}, 0.0, {}, style});
}
void DrawList::point(const Vec2& p, const Pen& style) { calls_.push_back({Kind::Point, {p}, 0.0, {}, style}); }
void DrawList::arrow(const Vec2& tail, const Vec2& head, const Pen& style) {
  calls_.push_back({Kind::Arrow, {tail, head}, 0.0, {}, style});
}
void DrawList::text(const Vec2& at, const std::string& text, const Pen& style) {
  calls_.push_back({Kind::Text, {at}, 0.0, text, style});
}

void DrawList::label(const Vec2& anchor, const Vec2& direction, const std::string& text, const Pen& style) {
  calls_.push_back({Kind::Label, {anchor, direction}, 0.0, text, style});
}

void DrawList::replay(Canvas& target, double opacity) const {
  for (const Call& c : calls_) {
    Pen s = c.style;
    s.opacity *= opacity;
    switch (c.kind) {
      case Kind::Polygon: target.polygon(c.points.vertices(), s); break;
      case Kind::Circle: target.circle(c.points[0], c.radius, s); break;
      case Kind::HalfPlane: target.halfPlane(c.points[0], c.points[1], s); break;
      case Kind::Segment: target.segment(c.points[0], c.points[1], s); break;
      case Kind::Point: target.point(c.points[0], s); break;
      case Kind::Arrow: target.arrow(c.points[0], c.points[1], s); break;
      case Kind::Text: target.text(c.points[0], c.text, s); break;
      case Kind::Label: target.label(c.points[0], c.points[1], c.text, s); break;
    }
  }
}

std::vector<std::string> DrawList::lines() const {
  std::vector<std::string> out;
  for (const Call& c : calls_) {
    std::string line;
    const std::string style = penName(c.style);
    switch (c.kind) {
      case Kind::Polygon:
        line.append("polygon ").append(style);
        for (const Vec2& v : c.points) line.append(" ").append(coordinates(v));
        break;
      case Kind::Circle:
        line.append("circle ").append(style).append(" ").append(coordinates(c.points[0])).append(" r=").append(number(c.radius));
        break;
      case Kind::HalfPlane:
        line.append("halfplane ")
            .append(style)
            .append(" ")
            .append(coordinates(c.points[0]))
            .append(" n=")
            .append(coordinates(c.points[1]));
        break;
      case Kind::Segment:
        line.append("segment ")
            .append(style)
            .append(" ")
            .append(coordinates(c.points[0]))
            .append(" ")
            .append(coordinates(c.points[1]));
        break;
      case Kind::Point: line.append("point ").append(style).append(" ").append(coordinates(c.points[0])); break;
      case Kind::Arrow:
        line.append("arrow ")
            .append(style)
            .append(" ")
            .append(coordinates(c.points[0]))
            .append(" -> ")
            .append(coordinates(c.points[1]));
        break;
      case Kind::Text:
        line.append("text ").append(style).append(" ").append(coordinates(c.points[0])).append(" \"").append(c.text).append("\"");
        break;
      case Kind::Label:
        line.append("label ")
            .append(style)
            .append(" ")
            .append(coordinates(c.points[0]))
            .append(" beyond ")
            .append(coordinates(c.points[1]))
            .append(" \"")
            .append(c.text)
            .append("\"");
        break;
    }
    out.push_back(std::move(line));
  }
  return out;
}

std::string DrawList::toText() const {
  std::string s;
  for (const std::string& line : lines()) s.append(line).append("\n");
  return s;
}

}  // namespace render::draw

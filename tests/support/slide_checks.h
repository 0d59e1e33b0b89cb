// What a slide promises (render/README.md, "A slide-ready frame"), checked on an image's draw list in
// its pixels: no two texts overlap, every text lies in the image, no panel meets a body or runs into
// a text that is not its own, no number
// shows round-off (a power of ten below 10⁻⁸), no time more than 3 decimals, no title repeats its
// letter ("A: A:"), no text cut ("…"). Each fault is one line naming the texts or calls.
#pragma once

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "render/frame/pixel_draw_list.h"

namespace slide_checks {

using render::frame::PixelBox;
using render::frame::PixelCall;
using render::frame::PixelDrawList;

// the points of a call, pairs of pixels
inline std::vector<sim::core::Vec2> pointsOf(const PixelCall& c) {
  std::vector<sim::core::Vec2> p;
  const size_t n = c.kind == "circle" ? 2 : c.numbers.size();
  for (size_t k = 0; k + 1 < n + 1 && k + 1 < c.numbers.size(); k += 2) p.emplace_back(c.numbers[k], c.numbers[k + 1]);
  return p;
}

// convex polygons (either winding) a and b overlap in more than a boundary (separating axes)
inline bool polygonsOverlap(const std::vector<sim::core::Vec2>& a, const std::vector<sim::core::Vec2>& b) {
  for (const auto* poly : {&a, &b})
    for (size_t i = 0; i < poly->size(); ++i) {
      const sim::core::Vec2 e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
      const sim::core::Vec2 axis(-e.y(), e.x());
      if (axis.norm() == 0.0) continue;
      double aLo = 1e300, aHi = -1e300, bLo = 1e300, bHi = -1e300;
      for (const auto& v : a) aLo = std::min(aLo, v.dot(axis)), aHi = std::max(aHi, v.dot(axis));
      for (const auto& v : b) bLo = std::min(bLo, v.dot(axis)), bHi = std::max(bHi, v.dot(axis));
      if (aHi <= bLo || bHi <= aLo) return false;
    }
  return true;
}

// a disc and a convex polygon overlap
inline bool discMeetsPolygon(const sim::core::Vec2& c, double r, const std::vector<sim::core::Vec2>& poly) {
  // inside, or within r of an edge
  bool inside = true;
  double winding = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    winding += a.x() * b.y() - b.x() * a.y();
  }
  for (size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    const sim::core::Vec2 d = b - a;
    if (winding * (d.x() * (c.y() - a.y()) - d.y() * (c.x() - a.x())) < 0.0) inside = false;
    const double s = d.squaredNorm() > 0.0 ? std::clamp((c - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    if ((c - (a + s * d)).norm() < r) return true;
  }
  return inside;
}

inline bool isBody(const PixelCall& c) {
  return (c.style.role == render::draw::Role::Body || c.style.role == render::draw::Role::StaticBody) &&
         (c.kind == "polygon" || c.kind == "circle");
}

// the least power of ten written in `text` ("× 10⁻¹³" → −13), or 0 without one
inline int leastPower(const std::string& text) {
  static const std::string kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  const std::string mark = "10⁻";
  int least = 0;
  for (size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 1)) {
    int n = 0;
    for (size_t k = at + mark.size();;) {
      int digit = -1;
      for (int d = 0; d < 10; ++d)
        if (text.compare(k, kDigits[d].size(), kDigits[d]) == 0) digit = d;
      if (digit < 0) break;
      n = 10 * n + digit, k += kDigits[digit].size();
    }
    least = std::min(least, -n);
  }
  return least;
}

// every fault of `list` against the promises above
inline std::vector<std::string> faults(const PixelDrawList& list) {
  std::vector<std::string> out;
  std::vector<const PixelCall*> texts, panels, bodies;
  for (const PixelCall& c : list.calls) {
    if (c.box) texts.push_back(&c);
    if (c.kind == "polygon" && c.style.role == render::draw::Role::Panel) panels.push_back(&c);
    if (isBody(c) && c.style.opacity == 1.0) bodies.push_back(&c);
    if (c.kind == "label") out.push_back("a label never placed: '" + c.text + "'");
  }
  for (size_t i = 0; i < texts.size(); ++i) {
    const PixelBox& b = *texts[i]->box;
    const std::string& t = texts[i]->text;
    if (b.left < 0 || b.top < 0 || b.right > list.width || b.bottom > list.height) out.push_back("'" + t + "' leaves the image");
    for (size_t j = i + 1; j < texts.size(); ++j)
      if (b.overlaps(*texts[j]->box)) out.push_back("'" + t + "' overlaps '" + texts[j]->text + "'");
    // round-off: 10⁻⁹ and smaller
    if (leastPower(t) < -8) out.push_back("'" + t + "' shows round-off as data");
    static const std::regex longTime("t = [0-9]+\\.[0-9]{4,}");
    if (std::regex_search(t, longTime)) out.push_back("'" + t + "' gives a time to more than 3 decimals");
    static const std::regex twice("^([A-Z]+): \\1:");
    if (std::regex_search(t, twice)) out.push_back("'" + t + "' repeats its letter");
    if (t.find("…") != std::string::npos) out.push_back("'" + t + "' is cut");
  }
  for (const PixelCall* p : panels) {
    const std::vector<sim::core::Vec2> panel = pointsOf(*p);
    // a text in the panel is one of its rows; one partly in it runs into it (the clock under it)
    PixelBox area{1e300, 1e300, -1e300, -1e300};
    for (const auto& v : panel)
      area.left = std::min(area.left, v.x()), area.right = std::max(area.right, v.x()), area.top = std::min(area.top, v.y()),
      area.bottom = std::max(area.bottom, v.y());
    for (const PixelCall* t : texts) {
      const PixelBox& b = *t->box;
      const bool inside = b.left >= area.left && b.right <= area.right && b.top >= area.top && b.bottom <= area.bottom;
      if (b.overlaps(area) && !inside) out.push_back("'" + t->text + "' runs into the panel");
    }
    for (const PixelCall* body : bodies) {
      const bool meets = body->kind == "circle" ? discMeetsPolygon(pointsOf(*body).front(), body->numbers[2], panel)
                                                : polygonsOverlap(panel, pointsOf(*body));
      if (meets) out.push_back("the panel meets " + body->pen);
    }
  }
  return out;
}

}  // namespace slide_checks

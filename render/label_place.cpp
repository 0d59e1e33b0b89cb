#include "label_place.h"

#include <cmath>

#include "text.h"

namespace render {

sim::Vec2 labelBeyond(const sim::Vec2& anchor, const sim::Vec2& direction, const std::string& text, double em) {
  // the half-extent of the box along the direction: its support distance
  const double halfWidth = 0.5 * approximateWidth(text, em), halfHeight = 0.5 * kLineHeight * em;
  const double reach = std::abs(direction.x()) * halfWidth + std::abs(direction.y()) * halfHeight;
  return anchor + direction * (reach + em / 3.0);
}

sim::Vec2 directionOr(const sim::Vec2& v, const sim::Vec2& fallback) {
  const double n = v.norm();
  return n > 0.0 ? sim::Vec2(v / n) : fallback;
}

}  // namespace render

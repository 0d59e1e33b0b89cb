#include "render/frame/label_place.h"

#include <cmath>

#include "render/draw/text.h"

namespace render::frame {
using namespace render::draw;

sim::core::Vec2 labelBeyond(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text, double em) {
  // the half-extent of the box along the direction: its support distance
  const double halfWidth = 0.5 * approximateWidth(text, em), halfHeight = 0.5 * kLineHeight * em;
  const double reach = std::abs(direction.x()) * halfWidth + std::abs(direction.y()) * halfHeight;
  return anchor + direction * (reach + em / 3.0);
}

sim::core::Vec2 directionOr(const sim::core::Vec2& v, const sim::core::Vec2& fallback) {
  const double n = v.norm();
  return n > 0.0 ? sim::core::Vec2(v / n) : fallback;
}

}  // namespace render::frame

// Where a label goes: beside what it names, clear of it, without measuring the text (the painter has
// no fonts; text.h's approximate width is enough to keep a box off an arrow).
#pragma once

#include <string>

#include "sim/core/math.h"

namespace render::frame {

// the center of `text`'s box (`em` its size, world units) lying beyond `anchor` in the unit
// `direction`, a third of a line clear of it
sim::core::Vec2 labelBeyond(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text, double em);

// a unit vector along v, or `fallback` when v has no length
sim::core::Vec2 directionOr(const sim::core::Vec2& v, const sim::core::Vec2& fallback);

}  // namespace render::frame

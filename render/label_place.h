// Where a label goes: beside what it names, clear of it, without measuring the text (the painter has
// no fonts; text.h's approximate width is enough to keep a box off an arrow).
#pragma once

#include <string>

#include "math.h"

namespace render {

// the center of `text`'s box (`em` its size, world units) lying beyond `anchor` in the unit
// `direction`, a third of a line clear of it
sim::Vec2 labelBeyond(const sim::Vec2& anchor, const sim::Vec2& direction, const std::string& text, double em);

// a unit vector along v, or `fallback` when v has no length
sim::Vec2 directionOr(const sim::Vec2& v, const sim::Vec2& fallback);

}  // namespace render

// The card a lecture video opens with: the title large and the scene's description wrapped below it,
// both centered on the background, and nothing else: no bodies, no clock, no caption, since the run
// has not started while the card shows.
#pragma once

#include <string>

#include "render/draw/image.h"
#include "render/draw/style.h"
#include "render/draw/text.h"

namespace render::frame {
using namespace render::draw;

// the card, `width` × `height` pixels; text sizes follow the style's font size (the title 2.2 times it)
Image composeTitleCard(int width, int height, const std::string& title, const std::string& description, const Style& style,
                       TextRenderer& text);

}  // namespace render::frame

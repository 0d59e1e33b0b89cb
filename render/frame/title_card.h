// The card a lecture video opens with: the first frame faded toward the background, the title large
// and the scene's description wrapped below it, both centered.
#pragma once

#include <string>

#include "render/draw/image.h"
#include "render/draw/style.h"
#include "render/draw/text.h"

namespace render::frame {
using namespace render::draw;

// `frame` with the card over it; text sizes follow the style's font size (the title 2.2 times it)
Image composeTitleCard(Image frame, const std::string& title, const std::string& description, const Style& style,
                       TextRenderer& text);

}  // namespace render::frame

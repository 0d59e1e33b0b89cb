// The poll slide: the same instant of every variant side by side (A | B | C), each under a title.
#pragma once

#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/draw/style.h"
#include "render/draw/text.h"

namespace render::frame {
using namespace render::draw;

// the frames left to right, each under its title, on the style's background with a thin rule
// between them; every frame must have the same size
Image composePanels(const std::vector<Image>& frames, const std::vector<std::string>& titles, const Style& style,
                    TextRenderer& text);

// "A", "B", …, "Z", "AA", … : the letter of the i-th panel (from 0)
std::string panelLetter(size_t i);

}  // namespace render::frame

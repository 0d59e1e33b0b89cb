// The cards a lecture video opens and may close with: a title large and a text wrapped below it,
// both centered on the background, and nothing else: no bodies, no clock, no caption. The opening
// card shows the poll's question (else the scene's description); the closing one, `answer_card`,
// the answer. A card's text is laid out whole: when it does not fit, its font shrinks, and a text
// that does not fit even at the smallest size is refused, never cut.
#pragma once

#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/draw/style.h"
#include "render/draw/text.h"
#include "render/frame/caption.h"

namespace render::frame {

// one line of a card: its text, the middle of its top edge in pixels, its size in pixels
struct CardLine {
  std::string text;
  double x = 0.0, y = 0.0;
  int size = 0;
};

struct CardLayout {
  std::vector<CardLine> lines;  // the title's, then the text's, top to bottom: what the card draws
  bool fits = true;             // false: the text does not fit even at the smallest size (lines empty)
};

// the widths of text at a size in pixels (TextRenderer::measure, or estimatedWidth in tests)
using SizedWidth = std::function<TextWidth(int sizePx)>;

// the card `width` × `height` pixels for a frame whose text is `fontSize` px: the title at 2.2 times
// it (at most 2 lines, "…" beyond), the text at 1.2 times it, both shrunk together one pixel of the
// text at a time, the text down to 0.75 times the font size (or height / 36 when smaller), until every
// word is on the card
CardLayout layoutCard(int width, int height, const std::string& title, const std::string& text, double fontSize,
                      const SizedWidth& widthAt);
// the card drawn from its layout
render::draw::Image composeCard(int width, int height, const CardLayout& layout, const render::draw::Style& style,
                                render::draw::TextRenderer& text);

// the card of a scene's video, 2D or 3D, `width` × `height` px: its title (titleOf) over its
// question (else its description), or, with `answer`, "Answer" over its answer. Throws
// sim::yaml::SceneError at the text's line when it cannot fit
CardLayout sceneCard(const render::scene::RenderDef& render, const std::string& name, const std::string& description, bool answer,
                     int width, int height, render::draw::TextRenderer& text);
// that card drawn in the style of the scene's frames
render::draw::Image composeSceneCard(const render::scene::RenderDef& render, const std::string& name,
                                     const std::string& description, bool answer, int width, int height,
                                     const render::draw::Style& style, render::draw::TextRenderer& text);

}  // namespace render::frame

// Text laid out to a width in pixels: the caption at the bottom of a frame and the description on
// the title card. Widths come from a function (TextRenderer::measure in frames; any rule in tests),
// so the lines are decided where the layout is, and draw lists show them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace render::frame {

// the width in pixels of a line of UTF-8 text
using TextWidth = std::function<int(const std::string&)>;

// where the caption goes in a frame whose text is `fontPx` high: lines `line` px apart, the last one
// ending `inset` px above the bottom (the time sits as far in from the top-left corner)
struct CaptionLayout {
  double inset = 0.0, line = 0.0;
  int maxLines = 2;
  // the band at the bottom of the frame the caption may take, px
  double band() const { return inset + maxLines * line; }
};
CaptionLayout captionLayout(int fontPx);

// a width without a font (draw lists made with no TextRenderer): 0.6 em per code point, about
// DejaVu Sans's average over prose
TextWidth estimatedWidth(int sizePx);

// `text` broken at spaces into lines at most `maxWidth` wide, at most `maxLines` of them; what does
// not fit ends the last line with "…" (a word wider than a line is cut, with "…")
std::vector<std::string> wrapLines(const std::string& text, int maxWidth, int maxLines, const TextWidth& width);

// the first sentence of `text` (up to the first '.', '!' or '?' followed by a space or the end),
// its runs of white space made single spaces
std::string firstSentence(const std::string& text);

// the caption the scene asks for: its `caption` text, the first sentence of its description, or ""
std::string captionOf(const render::scene::Scene& def);
// the same from a render: block (2D or 3D) and the scene's description
std::string captionOf(const render::scene::RenderDef& render, const std::string& description);

// the title of its card: `title`, or the scene's name with '_' as spaces
std::string titleOf(const render::scene::Scene& def);
std::string titleOf(const render::scene::RenderDef& render, const std::string& name);

}  // namespace render::frame

#include "render/frame/title_card.h"

#include <algorithm>
#include <cmath>

#include "render/frame/caption.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

namespace {

// the title and the description, as multiples of the frame's font size
constexpr double kTitleScale = 2.2, kDescriptionScale = 1.2;
// lines at most this fraction of the frame's width; a description of more lines ends with "…"
constexpr double kTitleWidth = 0.9, kDescriptionWidth = 0.75;
constexpr int kTitleLines = 2, kDescriptionLines = 6;

}  // namespace

Image composeTitleCard(int width, int height, const std::string& title, const std::string& description, const Style& style,
                       TextRenderer& text) {
  const Color& bg = style.background;
  Image frame(width, height, bg.withAlpha(1.0));
  const int titleSize = static_cast<int>(std::lround(kTitleScale * style.fontSize));
  const int bodySize = static_cast<int>(std::lround(kDescriptionScale * style.fontSize));
  const auto widthAt = [&text](int size) { return [&text, size](const std::string& s) { return text.measure(s, size).width; }; };
  const auto titleLines = wrapLines(title, static_cast<int>(kTitleWidth * frame.width), kTitleLines, widthAt(titleSize));
  const auto bodyLines =
      wrapLines(description, static_cast<int>(kDescriptionWidth * frame.width), kDescriptionLines, widthAt(bodySize));
  // the block of text centered vertically: title lines, half a title line of space, description lines
  const double titleLine = 1.2 * titleSize, bodyLine = 1.35 * bodySize;
  const double gap = bodyLines.empty() ? 0.0 : 0.5 * titleLine;
  const double block = titleLines.size() * titleLine + gap + bodyLines.size() * bodyLine;
  double y = std::round(0.5 * (frame.height - block));
  const double x = 0.5 * frame.width;
  for (const std::string& line : titleLines) {
    text.draw(frame, line, x, y, Anchor::TopCenter, titleSize, style.role(Role::Label), bg, std::max(1, titleSize / 10));
    y += titleLine;
  }
  y += gap;
  for (const std::string& line : bodyLines) {
    text.draw(frame, line, x, y, Anchor::TopCenter, bodySize, style.role(Role::Label), bg, std::max(1, bodySize / 10));
    y += bodyLine;
  }
  return frame;
}

}  // namespace render::frame

#include "render/frame/title_card.h"

#include <algorithm>
#include <cmath>

#include "render/frame/caption.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

namespace {

// how far the frame under the card fades toward the background: the bodies stay recognizable, the
// text reads over them
constexpr double kFade = 0.8;
// the title and the description, as multiples of the frame's font size
constexpr double kTitleScale = 2.2, kDescriptionScale = 1.2;
// lines at most this fraction of the frame's width; a description of more lines ends with "…"
constexpr double kTitleWidth = 0.9, kDescriptionWidth = 0.75;
constexpr int kTitleLines = 2, kDescriptionLines = 6;

}  // namespace

Image composeTitleCard(Image frame, const std::string& title, const std::string& description, const Style& style,
                       TextRenderer& text) {
  const Color& bg = style.background;
  const double target[3] = {bg.r, bg.g, bg.b};
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      uint8_t* p = frame.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = Color::byte(p[c] / 255.0 + (target[c] - p[c] / 255.0) * kFade);
    }
  const int titleSize = static_cast<int>(std::lround(kTitleScale * style.fontSize));
  const int bodySize = static_cast<int>(std::lround(kDescriptionScale * style.fontSize));
  const auto widthAt = [&text](int size) { return [&text, size](const std::string& s) { return text.measure(s, size).width; }; };
  const auto titleLines = wrapLines(title, static_cast<int>(kTitleWidth * frame.width), kTitleLines, widthAt(titleSize));
  const auto bodyLines =
      wrapLines(description, static_cast<int>(kDescriptionWidth * frame.width), kDescriptionLines, widthAt(bodySize));
  // the block of text centered vertically: title lines, half a title line of space, description lines
  const double titleLine = 1.2 * titleSize, bodyLine = 1.35 * bodySize;
  const double gap = bodyLines.empty() ? 0.0 : 0.5 * titleLine;
  const double height = titleLines.size() * titleLine + gap + bodyLines.size() * bodyLine;
  double y = std::round(0.5 * (frame.height - height));
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

#include "render/frame/panels.h"

#include <algorithm>
#include <cmath>

namespace render::frame {
using namespace render::draw;

std::string panelLetter(size_t i) {
  std::string s;
  for (size_t n = i + 1; n > 0; n = (n - 1) / 26) s.insert(s.begin(), static_cast<char>('A' + (n - 1) % 26));
  return s;
}

Image composePanels(const std::vector<Image>& frames, const std::vector<std::string>& titles, const Style& style,
                    TextRenderer& text) {
  if (frames.empty()) return {};
  const int w = frames.front().width, h = frames.front().height;
  // a title strip of twice the text size; a gap of about a 160th of a frame with a rule in it
  const int titleSize = std::max(12, static_cast<int>(std::lround(style.fontSize * 1.2)));
  const int strip = 2 * titleSize;
  const int gap = std::max(4, w / 160);
  const int n = static_cast<int>(frames.size());
  Image out(n * w + (n - 1) * gap, strip + h, style.background);
  const Color rule = style.background.mixed(style.role(Role::Label), 0.25);
  for (int i = 0; i < n; ++i) {
    const int x = i * (w + gap);
    paste(frames[i], out, x, strip);
    if (i < static_cast<int>(titles.size()))
      text.draw(out, titles[i], x + 0.5 * w, 0.5 * (strip - titleSize) - 0.1 * titleSize, Anchor::TopCenter, titleSize,
                style.role(Role::Label), style.background, 0);
    if (i + 1 < n) {
      const int rx = x + w + gap / 2 - 1;
      for (int y = 0; y < out.height; ++y)
        for (int dx = 0; dx < 2; ++dx) {
          uint8_t* p = out.pixel(rx + dx, y);
          p[0] = Color::byte(rule.r), p[1] = Color::byte(rule.g), p[2] = Color::byte(rule.b), p[3] = 255;
        }
    }
  }
  return out;
}

}  // namespace render::frame

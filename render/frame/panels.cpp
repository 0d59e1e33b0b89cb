#include "render/frame/panels.h"

#include <algorithm>
#include <cmath>

#include "render/frame/caption.h"
#include "render/jobs/exit_status.h"
#include "render/scene/render_def.h"

namespace render::frame {
using namespace render::draw;

namespace {

// the least share of a sheet's height a text takes: read from the back of a lecture hall
constexpr double kTextShare = 1.0 / 40.0;

int evenDown(double v) { return std::max(0, static_cast<int>(std::floor(v / 2.0)) * 2); }

// one pixel of `color` at (x, y) of `out`
void fill(Image& out, int x, int y, const Color& color) {
  uint8_t* p = out.pixel(x, y);
  p[0] = Color::byte(color.r), p[1] = Color::byte(color.g), p[2] = Color::byte(color.b), p[3] = 255;
}

}  // namespace

std::string panelLetter(size_t i) {
  std::string s;
  for (size_t n = i + 1; n > 0; n = (n - 1) / 26) s.insert(s.begin(), static_cast<char>('A' + (n - 1) % 26));
  return s;
}

int PanelGrid::frameX(size_t i) const { return static_cast<int>(i % columns) * (frameWidth + gap); }
int PanelGrid::frameY(size_t i) const { return static_cast<int>(i / columns) * (titleStrip + frameHeight + gap) + titleStrip; }

PanelGrid panelGrid(size_t count, int width, int height, bool caption, int columns, int captionLines) {
  PanelGrid g;
  g.sheetWidth = width, g.sheetHeight = height;
  const int n = static_cast<int>(std::max<size_t>(1, count));
  g.columns = n <= 2 ? n : n <= 4 ? 2 : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  if (columns > 0) g.columns = std::min(columns, n);
  g.rows = (n + g.columns - 1) / g.columns;
  g.textSize = std::max(1, static_cast<int>(std::ceil(kTextShare * height)));
  g.titleStrip = static_cast<int>(std::ceil(1.6 * g.textSize));
  g.gap = std::max(2, width / 240) / 2 * 2;
  g.captionLines = std::clamp(captionLines, 1, kMostCaptionLines);
  // a cell the variants leave empty holds the caption, rather than the sheet's height losing a band to it
  g.captionInCell = caption && n < g.columns * g.rows;
  g.captionBand = caption && !g.captionInCell ? static_cast<int>(std::ceil((g.captionLines * 1.25 + 0.5) * g.textSize)) : 0;
  g.frameWidth = evenDown((width - (g.columns - 1) * g.gap) / static_cast<double>(g.columns));
  g.frameHeight = evenDown((height - g.captionBand - (g.rows - 1) * g.gap) / static_cast<double>(g.rows) - g.titleStrip);
  if (g.frameWidth < render::scene::kMinFrameSide || g.frameHeight < render::scene::kMinFrameSide)
    throw render::jobs::UsageError("--panels: " + std::to_string(count) + " panels do not fit on a " + std::to_string(width) +
                                   "x" + std::to_string(height) + " sheet (" + std::to_string(g.columns) + " x " +
                                   std::to_string(g.rows) + ", each frame " + std::to_string(g.frameWidth) + "x" +
                                   std::to_string(g.frameHeight) + " px, under " + std::to_string(render::scene::kMinFrameSide) +
                                   "); give a larger --size (at most 8192 a side)");
  return g;
}

int sheetCaptionLines(const std::string& caption, int width, int height, TextRenderer& text) {
  // the sheet's text size, as panelGrid sets it
  const int size = std::max(1, static_cast<int>(std::ceil(kTextShare * height)));
  const auto lines = wrapLines(caption, width - 2 * size, kMostCaptionLines,
                               [&text, size](const std::string& s) { return text.measure(s, size).width; });
  return std::max<int>(1, static_cast<int>(lines.size()));
}

std::vector<SheetText> sheetTexts(const PanelGrid& g, size_t count, const std::vector<std::string>& titles,
                                  const std::string& caption, TextRenderer& text) {
  const auto widthAt = [&text](int size) { return [&text, size](const std::string& s) { return text.measure(s, size).width; }; };
  std::vector<SheetText> out;
  for (size_t i = 0; i < count && i < titles.size(); ++i) {
    // a title too long for its panel ends in "…" rather than run into the next
    const auto line = wrapLines(titles[i], g.frameWidth - g.textSize, 1, widthAt(g.textSize));
    if (!line.empty())
      out.push_back({line.front(),
                     {g.frameX(i) + 0.5 * g.frameWidth,
                      g.frameY(i) - g.titleStrip + 0.5 * (g.titleStrip - g.textSize) - 0.1 * g.textSize}});
  }
  // the caption once, in the empty cell (its title strip and frame), centered both ways
  if (!caption.empty() && g.captionInCell) {
    const size_t cell = count;
    const double top = g.frameY(cell) - g.titleStrip, height = g.titleStrip + g.frameHeight, line = 1.25 * g.textSize;
    const int most = std::max(1, static_cast<int>(std::floor(height / line)));
    const auto lines = wrapLines(caption, g.frameWidth - 2 * g.textSize, most, widthAt(g.textSize));
    double y = top + 0.5 * (height - line * static_cast<double>(lines.size()));
    for (const std::string& l : lines) {
      out.push_back({l, {g.frameX(cell) + 0.5 * g.frameWidth, y}});
      y += line;
    }
  }
  // the caption once, under the grid, centered
  if (!caption.empty() && g.captionBand > 0) {
    double y = g.sheetHeight - g.captionBand + 0.25 * g.textSize;
    for (const std::string& l : wrapLines(caption, g.sheetWidth - 2 * g.textSize, g.captionLines, widthAt(g.textSize))) {
      out.push_back({l, {0.5 * g.sheetWidth, y}});
      y += 1.25 * g.textSize;
    }
  }
  return out;
}

Image composePanels(const std::vector<Image>& frames, const PanelGrid& g, const std::vector<std::string>& titles,
                    const std::string& caption, const Style& style, TextRenderer& text) {
  Image out(g.sheetWidth, g.sheetHeight, style.background.withAlpha(1.0));
  const Color rule = style.background.mixed(style.role(Role::Label), 0.25);
  const Color& ink = style.role(Role::Label);
  for (size_t i = 0; i < frames.size(); ++i) paste(frames[i], out, g.frameX(i), g.frameY(i));
  // rules between the columns and between the rows, in the gaps
  const int gridBottom = g.sheetHeight - g.captionBand;
  for (int c = 1; c < g.columns; ++c) {
    const int rx = c * (g.frameWidth + g.gap) - g.gap / 2 - 1;
    for (int y = 0; y < gridBottom; ++y)
      for (int dx = 0; dx < 2; ++dx) fill(out, rx + dx, y, rule);
  }
  for (int r = 1; r < g.rows; ++r) {
    const int ry = r * (g.titleStrip + g.frameHeight + g.gap) - g.gap / 2 - 1;
    for (int x = 0; x < g.sheetWidth; ++x)
      for (int dy = 0; dy < 2; ++dy) fill(out, x, ry + dy, rule);
  }
  for (const SheetText& t : sheetTexts(g, frames.size(), titles, caption, text))
    text.draw(out, t.text, t.at.x(), t.at.y(), Anchor::TopCenter, g.textSize, ink, style.background, 0);
  return out;
}

PixelDrawList sheetDrawList(const std::vector<PixelDrawList>& cells, const PanelGrid& g, const std::vector<std::string>& titles,
                            const std::string& caption, const Style& style, TextRenderer& text) {
  PixelDrawList sheet{g.sheetWidth, g.sheetHeight, {}};
  for (size_t i = 0; i < cells.size(); ++i) addMoved(sheet, cells[i], g.frameX(i), g.frameY(i));
  const int line = text.measure("", g.textSize).ascent + text.measure("", g.textSize).descent;
  for (const SheetText& t : sheetTexts(g, cells.size(), titles, caption, text))
    addText(sheet, t.text, t.at, Anchor::TopCenter, text.measure(t.text, g.textSize).width, line, style.role(Role::Label));
  return sheet;
}

}  // namespace render::frame

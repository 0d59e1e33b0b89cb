#include "render/frame/title_card.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/scene/scene_style.h"
#include "sim/yaml/scene_error.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

namespace {

// the title and the text, as multiples of the frame's font size; both shrink to kLeastScale of that
constexpr double kTitleScale = 2.2, kTextScale = 1.2, kLeastScale = 0.75;
// lines at most this fraction of the frame's width, the block at most this fraction of its height
constexpr double kTitleWidth = 0.9, kTextWidth = 0.75, kBlockHeight = 0.9;
constexpr int kTitleLines = 2;

// `text`'s words separated by single spaces
std::string words(const std::string& text) {
  std::istringstream in(text);
  std::string out, word;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

}  // namespace

CardLayout layoutCard(int width, int height, const std::string& title, const std::string& text, double fontSize,
                      const SizedWidth& widthAt) {
  const std::string whole = words(text);
  // down to 3/4 of the text size, or of the frame's own proportion (height / 36) where the text size
  // is held up by its floor of 11 px: a 160 × 90 preview sets its card as a 1080p one, only smaller
  const double proportional = std::min(fontSize, height / 36.0);
  const int least = std::max(1, static_cast<int>(std::lround(kLeastScale * proportional)));
  for (int size = static_cast<int>(std::lround(kTextScale * fontSize)); size >= least; --size) {
    // the title shrinks with the text, keeping their proportion
    const int titleSize = std::max(1, static_cast<int>(std::lround(size * kTitleScale / kTextScale)));
    const auto titleLines = wrapLines(title, static_cast<int>(kTitleWidth * width), kTitleLines, widthAt(titleSize));
    const double titleLine = 1.2 * titleSize;
    // every word, on as many lines as it takes: the layout fits when none was cut and the block is on the card
    const int maxWidth = static_cast<int>(kTextWidth * width);
    const auto lines = wrapLines(whole, maxWidth, 1 << 20, widthAt(size));
    std::string joined;
    for (const std::string& l : lines) joined += (joined.empty() ? "" : " ") + l;
    const double line = 1.35 * size, gap = lines.empty() ? 0.0 : 0.5 * titleLine;
    const double block = titleLines.size() * titleLine + gap + lines.size() * line;
    if (joined != whole || block > kBlockHeight * height) continue;
    // the block centered vertically: title lines, half a title line of space, the text's lines
    CardLayout out;
    double y = std::round(0.5 * (height - block));
    for (const std::string& l : titleLines) out.lines.push_back({l, 0.5 * width, y, titleSize}), y += titleLine;
    y += gap;
    for (const std::string& l : lines) out.lines.push_back({l, 0.5 * width, y, size}), y += line;
    return out;
  }
  return {{}, false};
}

Image composeCard(int width, int height, const CardLayout& layout, const Style& style, TextRenderer& text) {
  const Color& bg = style.background;
  Image frame(width, height, bg.withAlpha(1.0));
  for (const CardLine& l : layout.lines)
    text.draw(frame, l.text, l.x, l.y, Anchor::TopCenter, l.size, style.role(Role::Label), bg, std::max(1, l.size / 10));
  return frame;
}

CardLayout sceneCard(const RenderDef& render, const std::string& name, const std::string& description, bool answer, int width,
                     int height, TextRenderer& text) {
  const PollDef& poll = render.poll;
  const std::string& shown = answer ? poll.answer : poll.question.empty() ? description : poll.question;
  const SizedWidth widthAt = [&text](int size) -> TextWidth {
    return [&text, size](const std::string& s) { return text.measure(s, size).width; };
  };
  CardLayout layout =
      layoutCard(width, height, answer ? "Answer" : titleOf(render, name), shown, fontSizeFor(render, height), widthAt);
  if (!layout.fits) {
    std::ostringstream size;
    size << width << "x" << height;
    throw sim::yaml::SceneError(poll.file, answer ? poll.answerLine : poll.line, answer ? poll.answerColumn : poll.column,
                                std::string(answer                  ? "the answer"
                                            : poll.question.empty() ? "the description"
                                                                    : "the question") +
                                    " does not fit on its card at " + size.str() +
                                    " even in the smallest type; shorten it (the card shows every word, never a cut line)");
  }
  return layout;
}

Image composeSceneCard(const RenderDef& render, const std::string& name, const std::string& description, bool answer, int width,
                       int height, const Style& style, TextRenderer& text) {
  return composeCard(width, height, sceneCard(render, name, description, answer, width, height, text), style, text);
}

}  // namespace render::frame

#include "render/frame/caption.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace render::frame {
using namespace render::scene;

namespace {

const std::string kEllipsis = "…";

// `line` without its last UTF-8 code point
void dropLastCodePoint(std::string& line) {
  while (!line.empty() && (static_cast<unsigned char>(line.back()) & 0xC0) == 0x80) line.pop_back();
  if (!line.empty()) line.pop_back();
}

// `line` shortened, by whole words when it has several, until it fits with "…" after it
std::string withEllipsis(std::string line, int maxWidth, const TextWidth& width) {
  while (!line.empty() && width(line + kEllipsis) > maxWidth) {
    const size_t space = line.rfind(' ');
    if (space != std::string::npos && space > 0) line.erase(space);
    else dropLastCodePoint(line);
  }
  return line + kEllipsis;
}

}  // namespace

CaptionLayout captionLayout(int fontPx) {
  // half a line of text in from the edges; lines a quarter of the size apart
  return {0.5 * fontPx, std::round(1.25 * fontPx)};
}

TextWidth estimatedWidth(int sizePx) {
  return [sizePx](const std::string& text) {
    const auto codePoints =
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
    return static_cast<int>(std::lround(0.6 * sizePx * static_cast<double>(codePoints)));
  };
}

std::vector<std::string> wrapLines(const std::string& text, int maxWidth, int maxLines, const TextWidth& width) {
  std::istringstream words(text);
  std::vector<std::string> lines;
  std::string line, word;
  bool cut = false;
  // greedy, as most typesetting of short text: each line takes words while they fit
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (line.empty() || width(longer) <= maxWidth) {
      line = longer;
      continue;
    }
    lines.push_back(line);
    line = word;
    if (static_cast<int>(lines.size()) == maxLines) {
      cut = true;
      break;
    }
  }
  if (!cut && !line.empty()) lines.push_back(line);
  for (size_t i = 0; i < lines.size(); ++i)
    if (width(lines[i]) > maxWidth || (cut && i + 1 == lines.size())) lines[i] = withEllipsis(lines[i], maxWidth, width);
  return lines;
}

std::string firstSentence(const std::string& text) {
  std::istringstream words(text);
  std::string sentence, word;
  while (words >> word) {
    sentence += (sentence.empty() ? "" : " ") + word;
    if (std::string(".!?").find(word.back()) != std::string::npos) break;
  }
  return sentence;
}

std::string captionOf(const render::scene::Scene& def) { return captionOf(def.render, def.model.description); }

std::string captionOf(const render::scene::RenderDef& render, const std::string& description) {
  if (!render.caption.empty()) return render.caption;
  return render.captionFromDescription ? firstSentence(description) : "";
}

std::string titleOf(const render::scene::Scene& def) { return titleOf(def.render, def.model.name); }

std::string titleOf(const render::scene::RenderDef& render, const std::string& name) {
  if (!render.title.empty()) return render.title;
  std::string title = name;
  std::replace(title.begin(), title.end(), '_', ' ');
  return title;
}

}  // namespace render::frame

// Text through FreeType: glyphs rasterized (8-bit anti-aliased coverage) with DejaVu Sans and
// blended straight into a frame, with a halo so that labels stay legible over bodies and lines.
// The notes' symbols are set as a slide sets them, no TeX needed: "v_n" is v with a lowered,
// smaller n, "x^2" a raised 2, "m_{eff}" a subscript of several letters (scriptRuns).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "render/draw/color.h"
#include "render/draw/image.h"

namespace render::draw {

// the font every frame is written in (Debian's fonts-dejavu-core)
inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// where the `at` point of a text lies on its box
enum class Anchor { Center, TopLeft, TopCenter };

struct TextBox {
  int width = 0;    // pixels, from the pen's start to its end
  int ascent = 0;   // pixels above the baseline (the font's, not the string's)
  int descent = 0;  // pixels below the baseline
};

class TextRenderer {
 public:
  // throws std::runtime_error naming the font when FreeType cannot load it
  explicit TextRenderer(const std::string& fontPath = kFontPath);
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  // the size of UTF-8 `text` at `sizePx` pixels per em
  TextBox measure(const std::string& text, int sizePx);
  // `text` blended into `image` with its `anchor` at pixel (x, y), surrounded by a halo of
  // `haloPx` pixels in `halo` (no halo when haloPx is 0)
  void draw(Image& image, const std::string& text, double x, double y, Anchor anchor, int sizePx, const Color& color,
            const Color& halo, int haloPx);

 private:
  struct Glyph {
    int left = 0, top = 0, width = 0, rows = 0;  // bitmap placement relative to the pen, y up
    int advance = 0;                             // 26.6 fixed point
    unsigned index = 0;                          // FreeType's glyph index, for kerning
    std::vector<uint8_t> coverage;
  };
  // a string's coverage and its halo, with `pad` pixels around the text box on every side
  struct Mask {
    TextBox box;
    int pad = 0, width = 0, height = 0;
    std::vector<uint8_t> coverage, halo;
  };
  using MaskKey = std::tuple<std::string, int, int>;  // text, size, halo

  const Glyph& glyph(char32_t code, int sizePx);
  // each glyph of `text` in order with the pen's position before it (26.6 fixed point, kerned) and
  // its baseline's shift down in pixels (a subscript's, a superscript's up), sub- and superscripts
  // at their smaller size; returns the pen after the last glyph: the advance of the whole line
  template <class Visit>
  long layOut(const std::string& text, int sizePx, Visit visit);
  const Mask& mask(const std::string& text, int sizePx, int haloPx);
  void setSize(int sizePx);

  struct Library;
  std::unique_ptr<Library> ft_;
  int size_ = 0;
  std::map<std::pair<char32_t, int>, Glyph> cache_;
  std::map<MaskKey, Mask> masks_;
};

// the code points of UTF-8 text (malformed bytes become U+FFFD)
std::u32string decodeUtf8(const std::string& text);

// a code point of a text as it is set: on the baseline, lowered (a subscript) or raised
struct ScriptRun {
  char32_t code;
  int script = 0;  // 0 on the baseline, −1 a subscript, +1 a superscript
};
// the code points of `text` with the markers of scripts taken out: '_' or '^' after a letter,
// before one letter or digit that ends a word ("v_n⁻", "x_b", "x^2"; not "mu_0.3" or "run_30",
// which stay as written), or before a braced group ("m_{eff}")
std::vector<ScriptRun> scriptRuns(const std::u32string& codes);
// about the width of `text` at `size` (any unit per em), without FreeType: for layouts made before any
// text is drawn; at least the true width for digits, letters and signs (DejaVu's digits are 0.64 em)
double approximateWidth(const std::string& text, double size);
// the height of a line of text at `size`: DejaVu Sans's ascent plus descent
inline constexpr double kLineHeight = 1.17;
// the same in whole pixels as TextRenderer::measure gives it at `sizePx`: FreeType rounds DejaVu Sans's
// ascender (1901 of 2048 units per em) and descender (483) outward
inline int lineHeightPx(int sizePx) { return (1901 * sizePx + 2047) / 2048 + (483 * sizePx + 2047) / 2048; }

}  // namespace render::draw

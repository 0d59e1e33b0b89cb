#include "render/draw/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace render::draw {

struct TextRenderer::Library {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
};

TextRenderer::TextRenderer(const std::string& fontPath) : ft_(std::make_unique<Library>()) {
  if (FT_Init_FreeType(&ft_->library)) throw std::runtime_error("FreeType could not start");
  if (FT_New_Face(ft_->library, fontPath.c_str(), 0, &ft_->face)) {
    FT_Done_FreeType(ft_->library);
    throw std::runtime_error(fontPath + ": cannot load the font (install fonts-dejavu-core)");
  }
}

TextRenderer::~TextRenderer() {
  FT_Done_Face(ft_->face);
  FT_Done_FreeType(ft_->library);
}

void TextRenderer::setSize(int sizePx) {
  if (size_ == sizePx) return;
  FT_Set_Pixel_Sizes(ft_->face, 0, static_cast<FT_UInt>(sizePx));
  size_ = sizePx;
}

const TextRenderer::Glyph& TextRenderer::glyph(char32_t code, int sizePx) {
  const auto key = std::make_pair(code, sizePx);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  setSize(sizePx);
  Glyph g;
  g.index = FT_Get_Char_Index(ft_->face, code);
  // FT_LOAD_RENDER: 8-bit anti-aliased coverage; a missing glyph draws the font's .notdef box
  if (FT_Load_Glyph(ft_->face, g.index, FT_LOAD_RENDER) == 0) {
    const FT_GlyphSlot slot = ft_->face->glyph;
    const FT_Bitmap& bm = slot->bitmap;
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.width = static_cast<int>(bm.width);
    g.rows = static_cast<int>(bm.rows);
    g.advance = static_cast<int>(slot->advance.x);
    g.coverage.resize(static_cast<size_t>(g.width) * g.rows);
    for (int r = 0; r < g.rows; ++r)
      std::copy_n(bm.buffer + r * bm.pitch, g.width, g.coverage.begin() + static_cast<ptrdiff_t>(r) * g.width);
  }
  return cache_.emplace(key, std::move(g)).first->second;
}

TextBox TextRenderer::measure(const std::string& text, int sizePx) {
  setSize(sizePx);
  const FT_Size_Metrics& m = ft_->face->size->metrics;
  TextBox box;
  box.ascent = static_cast<int>((m.ascender + 63) >> 6);
  box.descent = static_cast<int>((-m.descender + 63) >> 6);
  const long pen = layOut(text, sizePx, [](const Glyph&, long, int) {});
  box.width = static_cast<int>((pen + 63) >> 6);
  return box;
}

namespace {

// a script's size and its baseline's shift, as fractions of the text's size (TeX's proportions, about)
constexpr double kScriptSize = 0.7, kSubscriptDrop = 0.22, kSuperscriptRise = 0.38;

bool isLetter(char32_t c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= 0x391 && c <= 0x3C9); }
bool isAlnum(char32_t c) { return isLetter(c) || (c >= '0' && c <= '9'); }

}  // namespace

std::vector<ScriptRun> scriptRuns(const std::u32string& codes) {
  std::vector<ScriptRun> out;
  for (size_t i = 0; i < codes.size(); ++i) {
    const char32_t c = codes[i];
    const int script = c == U'_' ? -1 : c == U'^' ? 1 : 0;
    if (script != 0 && i > 0 && isLetter(codes[i - 1]) && i + 1 < codes.size()) {
      if (codes[i + 1] == U'{') {
        const size_t close = codes.find(U'}', i + 2);
        if (close != std::u32string::npos && close > i + 2) {
          for (size_t k = i + 2; k < close; ++k) out.push_back({codes[k], script});
          i = close;
          continue;
        }
      } else if (isAlnum(codes[i + 1])) {
        const char32_t after = i + 2 < codes.size() ? codes[i + 2] : U' ';
        if (!isAlnum(after) && after != U'.' && after != U'_' && after != U'^') {
          out.push_back({codes[i + 1], script});
          ++i;
          continue;
        }
      }
    }
    out.push_back({c, 0});
  }
  return out;
}

template <class Visit>
long TextRenderer::layOut(const std::string& text, int sizePx, Visit visit) {
  long pen = 0;
  unsigned previous = 0;
  int previousSize = 0;
  const int scriptSize = std::max(1, static_cast<int>(std::lround(kScriptSize * sizePx)));
  const int drop = static_cast<int>(std::lround(kSubscriptDrop * sizePx)),
            rise = static_cast<int>(std::lround(kSuperscriptRise * sizePx));
  for (const ScriptRun& run : scriptRuns(decodeUtf8(text))) {
    const int size = run.script == 0 ? sizePx : scriptSize;
    const Glyph& g = glyph(run.code, size);
    setSize(size);
    // kerning within one size only: a script's glyphs sit apart from the letter they follow
    if (previous && previousSize == size && FT_HAS_KERNING(ft_->face)) {
      FT_Vector k;
      FT_Get_Kerning(ft_->face, previous, g.index, FT_KERNING_DEFAULT, &k);
      pen += k.x;
    }
    visit(g, pen, run.script < 0 ? drop : run.script > 0 ? -rise : 0);
    pen += g.advance;
    previous = g.index;
    previousSize = size;
  }
  return pen;
}

const TextRenderer::Mask& TextRenderer::mask(const std::string& text, int sizePx, int haloPx) {
  const MaskKey key{text, sizePx, haloPx};
  if (auto it = masks_.find(key); it != masks_.end()) return it->second;
  // labels repeat from frame to frame; the time does not, so the cache is emptied now and then
  constexpr size_t kMaxMasks = 256;
  if (masks_.size() >= kMaxMasks) masks_.clear();

  Mask m;
  m.box = measure(text, sizePx);
  m.pad = haloPx + 1;
  m.width = m.box.width + 2 * m.pad + sizePx;
  // room below the text box for a subscript's descent (lowered past the font's)
  m.height = m.box.ascent + m.box.descent + 2 * m.pad + static_cast<int>(std::ceil(kSubscriptDrop * sizePx));
  m.coverage.assign(static_cast<size_t>(m.width) * m.height, 0);
  layOut(text, sizePx, [&m](const Glyph& g, long pen, int dy) {
    const int gx = m.pad + static_cast<int>(pen >> 6) + g.left, gy = m.pad + m.box.ascent - g.top + dy;
    for (int r = 0; r < g.rows; ++r)
      for (int col = 0; col < g.width; ++col) {
        const int mx = gx + col, my = gy + r;
        if (mx < 0 || my < 0 || mx >= m.width || my >= m.height) continue;
        uint8_t& v = m.coverage[static_cast<size_t>(my) * m.width + mx];
        v = std::max(v, g.coverage[static_cast<size_t>(r) * g.width + col]);
      }
  });
  if (haloPx > 0) {
    // the halo: the coverage dilated by a (2·haloPx + 1)² square, as a horizontal then a vertical
    // running maximum (separable; at 1-3 px a square looks the same as a disc)
    std::vector<uint8_t> rows(m.coverage.size(), 0);
    m.halo.assign(m.coverage.size(), 0);
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) {
        uint8_t best = 0;
        for (int d = std::max(0, x - haloPx); d <= std::min(m.width - 1, x + haloPx); ++d)
          best = std::max(best, m.coverage[static_cast<size_t>(y) * m.width + d]);
        rows[static_cast<size_t>(y) * m.width + x] = best;
      }
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) {
        uint8_t best = 0;
        for (int d = std::max(0, y - haloPx); d <= std::min(m.height - 1, y + haloPx); ++d)
          best = std::max(best, rows[static_cast<size_t>(d) * m.width + x]);
        m.halo[static_cast<size_t>(y) * m.width + x] = best;
      }
  }
  return masks_.emplace(key, std::move(m)).first->second;
}

void TextRenderer::draw(Image& image, const std::string& text, double x, double y, Anchor anchor, int sizePx, const Color& color,
                        const Color& halo, int haloPx) {
  const Mask& m = mask(text, sizePx, haloPx);
  // the pen's start on the baseline, whole pixels so that glyphs stay sharp
  double left = x, top = y;
  if (anchor == Anchor::Center || anchor == Anchor::TopCenter) left -= 0.5 * m.box.width;
  if (anchor == Anchor::Center) top -= 0.5 * (m.box.ascent + m.box.descent);
  const int x0 = static_cast<int>(std::lround(left)) - m.pad, y0 = static_cast<int>(std::lround(top)) - m.pad;

  // blend a coverage mask into the image, clipped to it: p + (c − p)·a in 8-bit integers
  auto blend = [&](const std::vector<uint8_t>& coverage, const Color& c) {
    const int rgb[3] = {Color::byte(c.r), Color::byte(c.g), Color::byte(c.b)};
    const int alpha = Color::byte(c.a);
    for (int my = std::max(0, -y0); my < m.height && y0 + my < image.height; ++my)
      for (int mx = std::max(0, -x0); mx < m.width && x0 + mx < image.width; ++mx) {
        const int cov = coverage[static_cast<size_t>(my) * m.width + mx];
        if (cov == 0) continue;
        const int a = (cov * alpha + 127) / 255;
        uint8_t* p = image.pixel(x0 + mx, y0 + my);
        for (int i = 0; i < 3; ++i) p[i] = static_cast<uint8_t>((p[i] * (255 - a) + rgb[i] * a + 127) / 255);
      }
  };
  if (haloPx > 0) blend(m.halo, halo);
  blend(m.coverage, color);
}

std::u32string decodeUtf8(const std::string& text) {
  std::u32string out;
  for (size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const int n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xe ? 3 : (b >> 3) == 0x1e ? 4 : 0;
    if (n == 0 || i + n > text.size()) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    char32_t c = n == 1 ? b : b & (0x7f >> n);
    bool ok = true;
    for (int k = 1; k < n; ++k) {
      const auto cont = static_cast<unsigned char>(text[i + k]);
      ok = ok && (cont >> 6) == 0x2;
      c = (c << 6) | (cont & 0x3f);
    }
    out.push_back(ok ? c : U'\uFFFD');
    i += ok ? n : 1;
  }
  return out;
}

double approximateWidth(const std::string& text, double size) {
  // combining marks (n̂) add no width
  const std::u32string codes = decodeUtf8(text);
  const auto marks = std::count_if(codes.begin(), codes.end(), [](char32_t c) { return c >= 0x300 && c < 0x370; });
  return 0.64 * size * static_cast<double>(codes.size() - static_cast<size_t>(marks));
}

}  // namespace render::draw

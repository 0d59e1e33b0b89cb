#include "text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace render {

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
  long pen = 0;
  unsigned previous = 0;
  for (char32_t c : decodeUtf8(text)) {
    const Glyph& g = glyph(c, sizePx);
    setSize(sizePx);
    if (previous && FT_HAS_KERNING(ft_->face)) {
      FT_Vector k;
      FT_Get_Kerning(ft_->face, previous, g.index, FT_KERNING_DEFAULT, &k);
      pen += k.x;
    }
    pen += g.advance;
    previous = g.index;
  }
  box.width = static_cast<int>((pen + 63) >> 6);
  return box;
}

void TextRenderer::draw(Image& image, const std::string& text, double x, double y, Anchor anchor, int sizePx,
                        const Color& color, const Color& halo, int haloPx) {
  const TextBox box = measure(text, sizePx);
  // the pen's start on the baseline, whole pixels so that glyphs stay sharp
  double left = x, top = y;
  if (anchor == Anchor::Center || anchor == Anchor::TopCenter) left -= 0.5 * box.width;
  if (anchor == Anchor::Center) top -= 0.5 * (box.ascent + box.descent);
  const int penX = static_cast<int>(std::lround(left)), baseline = static_cast<int>(std::lround(top)) + box.ascent;

  // the string's coverage in a mask with room for the halo around it
  const int pad = haloPx + 1;
  const int maskW = box.width + 2 * pad + sizePx, maskH = box.ascent + box.descent + 2 * pad;
  std::vector<uint8_t> mask(static_cast<size_t>(maskW) * maskH, 0);
  long pen = 0;
  unsigned previous = 0;
  for (char32_t c : decodeUtf8(text)) {
    const Glyph& g = glyph(c, sizePx);
    setSize(sizePx);
    if (previous && FT_HAS_KERNING(ft_->face)) {
      FT_Vector k;
      FT_Get_Kerning(ft_->face, previous, g.index, FT_KERNING_DEFAULT, &k);
      pen += k.x;
    }
    const int gx = pad + static_cast<int>(pen >> 6) + g.left, gy = pad + box.ascent - g.top;
    for (int r = 0; r < g.rows; ++r)
      for (int col = 0; col < g.width; ++col) {
        const int mx = gx + col, my = gy + r;
        if (mx < 0 || my < 0 || mx >= maskW || my >= maskH) continue;
        uint8_t& m = mask[static_cast<size_t>(my) * maskW + mx];
        m = std::max(m, g.coverage[static_cast<size_t>(r) * g.width + col]);
      }
    pen += g.advance;
    previous = g.index;
  }

  // blend a mask into the image at the mask's origin (x0, y0), clipped to the image
  const int x0 = penX - pad, y0 = baseline - box.ascent - pad;
  auto blend = [&](const std::vector<uint8_t>& coverage, const Color& c) {
    const double rgb[3] = {c.r * 255.0, c.g * 255.0, c.b * 255.0};
    for (int my = std::max(0, -y0); my < maskH && y0 + my < image.height; ++my)
      for (int mx = std::max(0, -x0); mx < maskW && x0 + mx < image.width; ++mx) {
        const int cov = coverage[static_cast<size_t>(my) * maskW + mx];
        if (cov == 0) continue;
        const double a = cov / 255.0 * c.a;
        uint8_t* p = image.pixel(x0 + mx, y0 + my);
        for (int i = 0; i < 3; ++i) p[i] = static_cast<uint8_t>(std::lround(p[i] + (rgb[i] - p[i]) * a));
      }
  };
  if (haloPx > 0) {
    // the halo: the coverage dilated by a disc of radius haloPx (a max filter)
    std::vector<uint8_t> grown(mask.size(), 0);
    for (int my = 0; my < maskH; ++my)
      for (int mx = 0; mx < maskW; ++mx) {
        uint8_t best = 0;
        for (int dy = -haloPx; dy <= haloPx; ++dy)
          for (int dx = -haloPx; dx <= haloPx; ++dx) {
            const int sx = mx + dx, sy = my + dy;
            if (dx * dx + dy * dy > haloPx * haloPx || sx < 0 || sy < 0 || sx >= maskW || sy >= maskH) continue;
            best = std::max(best, mask[static_cast<size_t>(sy) * maskW + sx]);
          }
        grown[static_cast<size_t>(my) * maskW + mx] = best;
      }
    blend(grown, halo);
  }
  blend(mask, color);
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

}  // namespace render

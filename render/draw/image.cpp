#include "render/draw/image.h"

#include <algorithm>
#include <cstring>

namespace render::draw {

Image::Image(int w, int h, const Color& fill) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4) {
  const uint8_t px[4] = {Color::byte(fill.r), Color::byte(fill.g), Color::byte(fill.b), Color::byte(fill.a)};
  for (size_t i = 0; i < rgba.size(); i += 4) std::memcpy(&rgba[i], px, 4);
}

Image downsample(const Image& image, int factor) {
  if (factor == 1) return image;
  Image out(image.width / factor, image.height / factor);
  const unsigned n = static_cast<unsigned>(factor * factor);
  // one row of sums per output row: walk the input rows in order, so memory is read sequentially
  std::vector<unsigned> sums(static_cast<size_t>(out.width) * 4);
  for (int y = 0; y < out.height; ++y) {
    std::fill(sums.begin(), sums.end(), 0u);
    for (int dy = 0; dy < factor; ++dy) {
      const uint8_t* row = image.pixel(0, y * factor + dy);
      for (int x = 0; x < out.width; ++x)
        for (int dx = 0; dx < factor; ++dx) {
          const uint8_t* p = row + (x * factor + dx) * 4;
          unsigned* s = &sums[static_cast<size_t>(x) * 4];
          s[0] += p[0], s[1] += p[1], s[2] += p[2], s[3] += p[3];
        }
    }
    uint8_t* o = out.pixel(0, y);
    for (size_t i = 0; i < sums.size(); ++i) o[i] = static_cast<uint8_t>((sums[i] + n / 2) / n);
  }
  return out;
}

void paste(const Image& source, Image& target, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(target.width, x + source.width);
  if (x1 <= x0) return;
  for (int row = std::max(0, y); row < std::min(target.height, y + source.height); ++row)
    std::memcpy(target.pixel(x0, row), source.pixel(x0 - x, row - y), static_cast<size_t>(x1 - x0) * 4);
}

}  // namespace render::draw

#include "render/draw/image_compare.h"

#include <algorithm>
#include <cstdlib>

namespace render::draw {

ImageComparison compareImages(const Image& expected, const Image& actual, const PixelTolerance& tolerance) {
  ImageComparison c;
  c.allowed = static_cast<long>(tolerance.fraction * expected.width * expected.height);
  if (expected.width != actual.width || expected.height != actual.height) {
    c.sameSize = false;
    return c;
  }
  c.diff = Image(expected.width, expected.height);
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x) {
      const uint8_t* e = expected.pixel(x, y);
      const uint8_t* a = actual.pixel(x, y);
      uint8_t* d = c.diff.pixel(x, y);
      int off = 0;
      for (int k = 0; k < 3; ++k) off = std::max(off, std::abs(e[k] - a[k]));
      c.largest = std::max(c.largest, off);
      if (off > tolerance.channel) {
        ++c.differing;
        d[0] = 255, d[1] = 0, d[2] = 0;
      } else {
        const uint8_t gray = static_cast<uint8_t>(191 + (e[0] + e[1] + e[2]) / 12);
        d[0] = d[1] = d[2] = gray;
      }
      d[3] = 255;
    }
  return c;
}

}  // namespace render::draw

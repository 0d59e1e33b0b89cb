// Two frames compared with a tolerance for rasterizer round-off (a new Mesa, another CPU's LLVM): a
// pixel differs when one of its channels is off by more than `channelTolerance` of 255, and the
// frames differ when more than `pixelFraction` of their pixels do. What our golden tests and
// `rigidreel golden check` both use.
#pragma once

#include "render/draw/image.h"

namespace render::draw {

struct PixelTolerance {
  int channel = 24;         // of 255
  double fraction = 0.002;  // of the pixels (0.2%: 115 of 320 × 180)
};

struct ImageComparison {
  bool sameSize = true;
  long differing = 0;  // pixels off by more than the channel tolerance
  long allowed = 0;    // the most that may be
  int largest = 0;     // the largest channel difference of any pixel, of 255
  Image diff;          // differing pixels in red over a faded copy of the expected frame
  bool passed() const { return sameSize && differing <= allowed; }
};

// `actual` against `expected` (RGB; alpha is not compared)
ImageComparison compareImages(const Image& expected, const Image& actual, const PixelTolerance& tolerance = {});

}  // namespace render::draw

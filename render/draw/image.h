// An RGBA8 image in memory, top row first: what a frame is between the GL read-back and the PNG or
// video encoder. Operations here are the ones the renderer needs (downsampling, pasting panels).
#pragma once

#include <cstdint>
#include <vector>

#include "render/draw/color.h"

namespace render::draw {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width × height × 4 bytes, row by row from the top

  Image() = default;
  Image(int w, int h, const Color& fill = {1.0, 1.0, 1.0, 1.0});
  uint8_t* pixel(int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  const uint8_t* pixel(int x, int y) const { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  bool operator==(const Image&) const = default;
};

// each factor × factor block averaged into one pixel (the box filter of supersampling), rounded
Image downsample(const Image& image, int factor);

// `source` copied into `target` with its top-left corner at (x, y), clipped to `target`
void paste(const Image& source, Image& target, int x, int y);

}  // namespace render::draw

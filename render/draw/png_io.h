// PNG files through libpng: frames out (RGB, 8 bits, settings chosen by measurement) and images in
// (any PNG, as RGBA8) for the golden-image tests. Named png_io so that <png.h> stays libpng's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/draw/image.h"

namespace render::draw {

// zlib level, row filters (PNG_FILTER_* bits) and zlib strategy (Z_*)
struct PngSettings {
  int level;
  int filters;
  int strategy;
};

// the settings frames are written with; see png.cpp for the measurement behind them
PngSettings defaultPngSettings();

// the image as PNG bytes (alpha dropped: frames are opaque); throws std::runtime_error
std::vector<uint8_t> encodePng(const Image& image, const PngSettings& settings = defaultPngSettings());
// written under a temporary name and renamed; throws std::runtime_error naming the path
void writePng(const Image& image, const std::string& path, const PngSettings& settings = defaultPngSettings());
// any PNG as RGBA8, read through render/jobs/bounded_read.h (at most kMaxPngBytes, a FIFO
// refused); throws std::runtime_error naming the path
Image readPng(const std::string& path);

// a PNG's width and height as its header says, px: read before decoding, so that a 120-byte file
// claiming 30000 × 30000 pixels is told apart before 3.6 GB are allocated for it
struct PngSize {
  long width = 0, height = 0;
};
// the header of the PNG in `bytes` (read from `path`, which messages name); throws std::runtime_error
PngSize pngSize(const std::string& bytes, const std::string& path);
// the PNG in `bytes` as RGBA8; throws std::runtime_error naming `path`
Image decodePng(const std::string& bytes, const std::string& path);

}  // namespace render::draw

#include "render/draw/png_io.h"

#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <stdexcept>

#include "render/jobs/atomic_file.h"
#include "render/jobs/bounded_read.h"
#include "render/jobs/read_limits.h"

namespace render::draw {
using namespace render::jobs;

namespace {

struct ErrorSink {
  char message[256] = "";
};

void onError(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message);
  png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, size_t n) {
  auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + n);
}

void flushNothing(png_structp) {}

// libpng reports errors by longjmp, which skips destructors: this frame holds none
bool encodeRaw(const Image& image, const PngSettings& s, std::vector<uint8_t>* out, ErrorSink* sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, sink, onError, onWarning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, appendBytes, flushNothing);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, s.level);
  png_set_compression_strategy(png, s.strategy);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, s.filters);
  png_write_info(png, info);
  // the rows are RGBA: libpng drops the fourth byte of each pixel
  png_set_filler(png, 0, PNG_FILLER_AFTER);
  for (int y = 0; y < image.height; ++y) png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

// zlib level 3, no row filter. Measured by build/rigidreel_frame_bench (render/bench/frame_bench.cpp) on a
// 1280×720 frame, milliseconds and bytes per encoding:
//   libpng's default (level 6, all filters, Z_FILTERED) 30.9 ms 22.0 kB | level 9, none 33.9 ms 15.9 kB
//   level 6, none 15.8 ms 20.1 kB | level 3, none 5.6 ms 33.0 kB | level 1, none 5.6 ms 36.7 kB
//   level 1, sub 7.3 ms 38.0 kB | level 1, up, Z_RLE 8.1 ms 99.2 kB
// Flat fills with anti-aliased edges compress best unfiltered: a filter turns each edge into two
// runs of residues. Level 3 is 5.5× faster than libpng's default for half as many bytes again;
// frames beside a video are many and small (30 kB), and written beside the rendering, so time wins.
PngSettings defaultPngSettings() { return {3, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}; }

std::vector<uint8_t> encodePng(const Image& image, const PngSettings& settings) {
  std::vector<uint8_t> out;
  ErrorSink sink;
  if (!encodeRaw(image, settings, &out, &sink)) throw std::runtime_error(std::string("PNG encoding failed: ") + sink.message);
  return out;
}

void writePng(const Image& image, const std::string& path, const PngSettings& settings) {
  const std::vector<uint8_t> bytes = encodePng(image, settings);
  AtomicFile file(path);
  file.stream().write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

namespace {

// libpng's simplified API converts any PNG to RGBA8 and reports errors without longjmp; the header
// read alone, nothing decoded yet
png_image beginRead(const std::string& bytes, const std::string& path) {
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&info, bytes.data(), bytes.size()))
    throw std::runtime_error(path + ": cannot read PNG (" + info.message + ")");
  return info;
}

}  // namespace

PngSize pngSize(const std::string& bytes, const std::string& path) {
  png_image info = beginRead(bytes, path);
  const PngSize size{static_cast<long>(info.width), static_cast<long>(info.height)};
  png_image_free(&info);
  return size;
}

Image decodePng(const std::string& bytes, const std::string& path) {
  png_image info = beginRead(bytes, path);
  info.format = PNG_FORMAT_RGBA;
  Image image;
  image.width = static_cast<int>(info.width);
  image.height = static_cast<int>(info.height);
  image.rgba.resize(PNG_IMAGE_SIZE(info));
  if (!png_image_finish_read(&info, nullptr, image.rgba.data(), 0, nullptr)) {
    const std::string message = info.message;
    png_image_free(&info);
    throw std::runtime_error(path + ": cannot read PNG (" + message + ")");
  }
  return image;
}

Image readPng(const std::string& path) { return decodePng(readBounded(path, kMaxPngBytes, "PNG", "give a PNG image"), path); }

}  // namespace render::draw

#include "render/page/media_info.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <vector>

namespace render::page {

namespace {

using Bytes = std::vector<uint8_t>;

uint64_t bigEndian(const Bytes& b, size_t at, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | b[at + i];
  return v;
}

// the file's first `limit` bytes (a header is near the start; +faststart puts the movie box there)
Bytes head(const std::string& path, size_t limit) {
  std::ifstream in(path, std::ios::binary);
  Bytes b(limit);
  in.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(limit));
  b.resize(static_cast<size_t>(in.gcount()));
  return b;
}

// the boxes inside [from, to): calls `visit(type, bodyStart, bodyEnd)` for each
// sizes are checked against what is left (to - at), never by adding to `at`: a 64-bit size near
// 2⁶⁴ would wrap the sum, and the walk would start over forever
template <class Visit>
void boxes(const Bytes& b, size_t from, size_t to, Visit visit) {
  for (size_t at = from; at < to && to - at >= 8;) {
    uint64_t size = bigEndian(b, at, 4);
    size_t header = 8;
    if (size == 1) {  // a 64-bit size follows the type
      if (to - at < 16) return;
      size = bigEndian(b, at + 8, 8), header = 16;
    } else if (size == 0) {  // to the end
      size = to - at;
    }
    if (size < header || size > to - at) return;
    visit(std::string_view(reinterpret_cast<const char*>(&b[at + 4]), 4), at + header, at + size);
    at += size;
  }
}

}  // namespace

std::optional<MediaInfo> pngInfo(const std::string& path) {
  // the signature, then IHDR: length, "IHDR", width, height
  const Bytes b = head(path, 24);
  static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() < 24 || !std::equal(signature, signature + 8, b.begin()) ||
      std::string_view(reinterpret_cast<const char*>(&b[12]), 4) != "IHDR")
    return std::nullopt;
  return MediaInfo{static_cast<int>(bigEndian(b, 16, 4)), static_cast<int>(bigEndian(b, 20, 4)), 0.0};
}

// the body of the file's top-level `moov` box, found by reading box headers and seeking past the
// rest (the media data may be hundreds of megabytes). Each box must fit in what is left of the file,
// so every seek goes forward and the walk ends.
Bytes movieBox(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return {};
  const uint64_t fileSize = static_cast<uint64_t>(in.tellg());
  in.seekg(0);
  for (uint64_t at = 0; at < fileSize;) {
    Bytes header(16);
    if (!in.read(reinterpret_cast<char*>(header.data()), 8)) return {};
    uint64_t size = bigEndian(header, 0, 4), headerSize = 8;
    if (size == 1) {
      if (!in.read(reinterpret_cast<char*>(header.data()) + 8, 8)) return {};
      size = bigEndian(header, 8, 8), headerSize = 16;
    }
    if (size == 0 || size < headerSize || size > fileSize - at) return {};
    at += size;
    const uint64_t body = size - headerSize;
    if (std::string_view(reinterpret_cast<const char*>(&header[4]), 4) == "moov") {
      // a movie header of a few kilobytes per minute of video; refuse an absurd one
      if (body > (64u << 20)) return {};
      Bytes b(body);
      if (!in.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(body))) return {};
      return b;
    }
    in.seekg(static_cast<std::streamoff>(at));
  }
  return {};
}

std::optional<MediaInfo> mp4Info(const std::string& path) {
  const Bytes b = movieBox(path);
  MediaInfo info;
  bool duration = false;
  boxes(b, 0, b.size(), [&](std::string_view type, size_t begin, size_t end) {
    // mvhd: version, flags, then (version 1: 64-bit) creation and modification times, the
    // timescale (units per second) and the duration in those units
    if (type == "mvhd" && end > begin) {
      const bool v1 = b[begin] == 1;
      const size_t at = begin + 4 + (v1 ? 16 : 8);
      if (at + (v1 ? 12 : 8) > end) return;
      const uint64_t scale = bigEndian(b, at, 4), units = bigEndian(b, at + 4, v1 ? 8 : 4);
      if (scale > 0) info.duration = static_cast<double>(units) / static_cast<double>(scale), duration = true;
    }
    // trak → tkhd: its last 8 bytes are the width and height, 16.16 fixed point
    if (type == "trak" && info.width == 0)
      boxes(b, begin, end, [&](std::string_view type, size_t begin, size_t end) {
        if (type != "tkhd" || end < begin + 8) return;
        const uint64_t w = bigEndian(b, end - 8, 4) >> 16, h = bigEndian(b, end - 4, 4) >> 16;
        if (w > 0 && h > 0) info.width = static_cast<int>(w), info.height = static_cast<int>(h);
      });
  });
  if (!duration || info.width == 0) return std::nullopt;
  return info;
}

}  // namespace render::page

#include "render/video/container_check.h"

#include <cstdint>
#include <fstream>
#include <optional>
#include <vector>

namespace render::video {

namespace {

// big-endian reads at an offset of an open file; nullopt past the end
class FileBytes {
 public:
  explicit FileBytes(const std::string& path) : in_(path, std::ios::binary | std::ios::ate) {
    if (in_) size_ = static_cast<uint64_t>(in_.tellg());
  }
  bool open() const { return static_cast<bool>(in_); }
  uint64_t size() const { return size_; }
  std::optional<std::vector<uint8_t>> bytes(uint64_t at, size_t n) {
    if (at > size_ || n > size_ - at) return std::nullopt;
    std::vector<uint8_t> b(n);
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(n));
    if (!in_) return std::nullopt;
    return b;
  }
  std::optional<uint64_t> bigEndian(uint64_t at, size_t n) {
    const auto b = bytes(at, n);
    if (!b) return std::nullopt;
    uint64_t v = 0;
    for (uint8_t c : *b) v = v << 8 | c;
    return v;
  }

 private:
  std::ifstream in_;
  uint64_t size_ = 0;
};

// an MP4 box (ISO/IEC 14496-12 §4.2): its type, where its content starts and where it ends
struct Box {
  std::string type;
  uint64_t content = 0, end = 0;
};

// the boxes in [from, to); nullopt when one runs past `to` (a truncated file)
std::optional<std::vector<Box>> boxes(FileBytes& f, uint64_t from, uint64_t to) {
  std::vector<Box> out;
  while (from < to) {
    const auto size32 = f.bigEndian(from, 4);
    const auto type = f.bytes(from + 4, 4);
    if (!size32 || !type) return std::nullopt;
    Box b{std::string(type->begin(), type->end()), from + 8, 0};
    uint64_t size = *size32;
    if (size == 1) {  // a 64-bit size follows the type
      const auto large = f.bigEndian(from + 8, 8);
      if (!large) return std::nullopt;
      size = *large;
      b.content += 8;
    } else if (size == 0) {  // the box runs to the end of the file
      size = to - from;
    }
    if (size < b.content - from || size > to - from) return std::nullopt;
    b.end = from + size;
    out.push_back(b);
    from = b.end;
  }
  return out;
}

std::optional<Box> child(FileBytes& f, const Box& parent, const std::string& type) {
  const auto inside = boxes(f, parent.content, parent.end);
  if (!inside) return std::nullopt;
  for (const Box& b : *inside)
    if (b.type == type) return b;
  return std::nullopt;
}

std::string mp4Defect(FileBytes& f, long frames) {
  const auto top = boxes(f, 0, f.size());
  if (!top) return "its last box runs past the end of the file (the file is truncated)";
  std::optional<Box> moov;
  bool mdat = false;
  for (const Box& b : *top) {
    if (b.type == "moov") moov = b;
    mdat = mdat || b.type == "mdat";
  }
  if (!moov || !mdat) return "it has no index (moov box) or no frames (mdat box)";
  // moov → trak → mdia → minf → stbl → stsz: the video track's sample count (one per frame)
  std::optional<Box> at = moov;
  for (const char* type : {"trak", "mdia", "minf", "stbl", "stsz"})
    if (at) at = child(f, *at, type);
  if (!at) return "its index has no sample table (moov/trak/mdia/minf/stbl/stsz)";
  const auto samples = f.bigEndian(at->content + 8, 4);  // after version, flags and sample_size
  if (!samples || *samples != static_cast<uint64_t>(frames))
    return "it holds " + std::to_string(samples.value_or(0)) + " frames, not the " + std::to_string(frames) + " written";
  return "";
}

// an EBML variable-length integer (RFC 8794 §4): its value and length; `marker` keeps the length
// bits (element IDs) or drops them (sizes). An unknown size (all value bits set) gives nullopt.
std::optional<std::pair<uint64_t, size_t>> vint(FileBytes& f, uint64_t at, bool marker) {
  const auto first = f.bigEndian(at, 1);
  if (!first || *first == 0) return std::nullopt;
  size_t length = 1;
  while (!(*first & (0x80u >> (length - 1)))) ++length;
  const auto raw = f.bigEndian(at, length);
  if (!raw) return std::nullopt;
  const uint64_t valueBits = (uint64_t{1} << (7 * length)) - 1;
  if (marker) return std::pair{*raw, length};
  if ((*raw & valueBits) == valueBits) return std::nullopt;
  return std::pair{*raw & valueBits, length};
}

std::string webmDefect(FileBytes& f) {
  // the EBML header, then one Segment whose size the muxer writes last, at the trailer
  uint64_t at = 0;
  for (const uint64_t id : {uint64_t{0x1A45DFA3}, uint64_t{0x18538067}}) {
    const auto element = vint(f, at, true);
    if (!element || element->first != id) return "it does not start with a WebM header and segment";
    const auto size = vint(f, at + element->second, false);
    if (!size) return "its segment has no size (the muxer's trailer was not written)";
    // against what is left, not by adding: a size near 2⁶⁴ would wrap the sum
    const uint64_t header = element->second + size->second;
    if (size->first > f.size() - at - header) return "its segment runs past the end of the file";
    at += header + size->first;
  }
  if (at != f.size()) return "its segment ends at byte " + std::to_string(at) + ", not at the file's end";
  return "";
}

std::string gifDefect(FileBytes& f) {
  const auto header = f.bytes(0, 13);
  if (!header || std::string(header->begin(), header->begin() + 3) != "GIF") return "it has no GIF header";
  uint64_t at = 13;
  if ((*header)[10] & 0x80) at += 3u << (((*header)[10] & 7) + 1);  // the global colour table
  // blocks up to the trailer (GIF89a): extensions and images, each ending in a chain of sub-blocks
  for (;;) {
    const auto kind = f.bigEndian(at, 1);
    if (!kind) return "it ends before its trailer (the file is truncated)";
    if (*kind == 0x3B) return at + 1 == f.size() ? "" : "it has data after its trailer";
    if (*kind == 0x21) {
      at += 2;
    } else if (*kind == 0x2C) {
      const auto flags = f.bigEndian(at + 9, 1);
      if (!flags) return "it ends inside an image (the file is truncated)";
      at += 10 + ((*flags & 0x80) ? 3u << ((*flags & 7) + 1) : 0) + 1;
    } else {
      return "it has an unknown block at byte " + std::to_string(at);
    }
    for (auto n = f.bigEndian(at, 1); n && *n; n = f.bigEndian(at, 1)) at += 1 + *n;
    if (!f.bigEndian(at, 1)) return "it ends inside a block (the file is truncated)";
    ++at;
  }
}

}  // namespace

std::string videoDefect(const std::string& path, VideoFormat format, long frames) {
  FileBytes f(path);
  if (!f.open()) return "it cannot be read back";
  switch (format) {
    case VideoFormat::Mp4: return mp4Defect(f, frames);
    case VideoFormat::Webm: return webmDefect(f);
    case VideoFormat::Gif: return gifDefect(f);
  }
  return "";
}

}  // namespace render::video

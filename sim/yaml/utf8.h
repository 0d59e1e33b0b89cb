// Text read from a scene (names, labels, titles) goes into JSON, CSV and other outputs, all UTF-8:
// bytes that are not UTF-8 (a file saved as Latin-1) are refused where they are read.
#pragma once

#include <cstddef>
#include <string_view>

namespace sim::yaml {

// the offset of the first byte that does not begin or continue a well-formed UTF-8 sequence
// (RFC 3629: no overlong forms, no surrogates, nothing past U+10FFFF), or npos when all are
inline size_t invalidUtf8At(std::string_view s) {
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || i + length > s.size() || c == 0xC0 || c == 0xC1 || c > 0xF4) return i;
    for (size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return i;
    const unsigned char d = length > 1 ? static_cast<unsigned char>(s[i + 1]) : 0;
    // overlong three- and four-byte forms, UTF-16 surrogates, code points past U+10FFFF
    if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d >= 0xA0) || (c == 0xF0 && d < 0x90) || (c == 0xF4 && d >= 0x90)) return i;
    i += length;
  }
  return std::string_view::npos;
}

}  // namespace sim::yaml

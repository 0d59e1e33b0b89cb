#include "sim/yaml/path_name.h"

#include <string>

namespace sim::yaml {

std::string pathNameFault(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxNameBytes) return "is longer than " + std::to_string(kMaxNameBytes) + " bytes";
  if (name.front() == '.') return "starts with '.' (a hidden file, or a way out of the output folder)";
  if (name.front() == '-') return "starts with '-' (programs would read it as an option)";
  for (const char c : name) {
    if (c == '/' || c == '\\') return std::string("contains '") + c + "' (a folder separator)";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "contains a control character";
  }
  return "";
}

std::string shownName(std::string_view name) {
  std::string shown;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      shown += c;
      continue;
    }
    const char* digits = "0123456789abcdef";
    shown += "\\x";
    shown += digits[byte >> 4];
    shown += digits[byte & 15];
  }
  return shown;
}

}  // namespace sim::yaml

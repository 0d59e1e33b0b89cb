#include "render/cli/yaml_scalar.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>

namespace render::cli {

namespace {

// words YAML 1.1 or 1.2 reads as null or a boolean
bool reservedWord(std::string_view text) {
  static const std::array<std::string_view, 11> words = {"null", "~", "true", "false", "yes", "no", "on", "off", "y", "n", ""};
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::find(words.begin(), words.end(), lower) != words.end();
}

// letters (any non-ASCII byte), digits, '_', '-', '.' and inner single spaces, starting with a
// letter or '_': never a number, an indicator or a flow separator
bool plainWord(std::string_view text) {
  const auto letter = [](unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; };
  if (text.empty() || !letter(static_cast<unsigned char>(text.front())) || text.back() == ' ') return false;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (letter(c) || std::isdigit(c) || c == '-' || c == '.') continue;
    if (c == ' ' && text[i + 1] != ' ') continue;
    return false;
  }
  return !reservedWord(text);
}

}  // namespace

std::string yamlScalar(std::string_view text) {
  if (plainWord(text)) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\', out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace render::cli

// Colors as the renderer uses them: linear 0..1 components (GL's), parsed from the scene's "#rrggbb".
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace render::draw {

struct Color {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;

  // "#rrggbb" (the scene reader has checked the form); throws std::invalid_argument otherwise
  static Color parse(const std::string& hex) {
    if (hex.size() != 7 || hex[0] != '#') throw std::invalid_argument("not a \"#rrggbb\" color: '" + hex + "'");
    const unsigned long v = std::stoul(hex.substr(1), nullptr, 16);
    return {((v >> 16) & 0xff) / 255.0, ((v >> 8) & 0xff) / 255.0, (v & 0xff) / 255.0, 1.0};
  }
  // this color moved toward `other` by `amount` (0: unchanged, 1: other); alpha kept
  Color mixed(const Color& other, double amount) const {
    return {r + (other.r - r) * amount, g + (other.g - g) * amount, b + (other.b - b) * amount, a};
  }
  Color withAlpha(double alpha) const { return {r, g, b, alpha}; }
  // an 8-bit component, rounded
  static uint8_t byte(double c) { return static_cast<uint8_t>(c <= 0.0 ? 0 : c >= 1.0 ? 255 : c * 255.0 + 0.5); }
  // "#rrggbb", as a scene writes it (alpha left out)
  std::string hex() const {
    static const char* const kDigits = "0123456789abcdef";
    std::string s = "#";
    for (double c : {r, g, b}) s += kDigits[byte(c) >> 4], s += kDigits[byte(c) & 15];
    return s;
  }
};

}  // namespace render::draw

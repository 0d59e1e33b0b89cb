#include "render/cli/decimal_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace render::cli {

std::optional<double> decimalText(const std::string& text) {
  const char* begin = text.c_str();
  while (std::isspace(static_cast<unsigned char>(*begin))) ++begin;
  if (*begin == '\0') return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  while (std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (*end != '\0' || end != text.c_str() + text.size()) return std::nullopt;
  // ERANGE with a finite result is an underflow (subnormal or 0): the value strtod gives is the
  // nearest double, kept; an overflow gives ±HUGE_VAL, refused below with NaN
  if (!std::isfinite(x)) return std::nullopt;
  return x + 0.0;  // −0 + 0 is +0
}

}  // namespace render::cli

#include "sim/describe/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sim::describe {

namespace {

const char* const kMinus = "\u2212";

// "⁻¹³": an exponent in superscript digits
std::string superscript(int n) {
  static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string digits = std::to_string(std::abs(n)), out = n < 0 ? "⁻" : "";
  for (char c : digits) out += kDigits[c - '0'];
  return out;
}

// |x| (finite, positive) to `digits` significant digits in plain notation, rounded once by printf
std::string plain(double x, int digits) {
  int exponent = static_cast<int>(std::floor(std::log10(x)));
  char buf[64];
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int decimals = digits - 1 - exponent;
    // past the point (1234.5 to three digits: 1230), rounded to the last significant place first
    const double place = decimals < 0 ? std::pow(10.0, -decimals) : 1.0;
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, decimals), decimals < 0 ? std::round(x / place) * place : x);
    // rounding carried into a new digit (9.996 → "10.00"): one decimal fewer
    if (std::strtod(buf, nullptr) < std::pow(10.0, exponent + 1)) break;
    ++exponent;
  }
  return buf;
}

}  // namespace

std::string numberText(double x, int digits, double zeroBelow) {
  digits = std::clamp(digits, 1, 17);
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "∞" : std::string(kMinus) + "∞";
  const double a = std::abs(x);
  if (a == 0.0 || a < zeroBelow) return "0";
  std::string body;
  if (a >= 1e-3 && a < 1e4) {
    body = plain(a, digits);
    // 10,000 reached by rounding (9999.7): written with a power of ten below
    if (std::strtod(body.c_str(), nullptr) >= 1e4) body.clear();
  }
  if (body.empty()) {
    // m × 10ⁿ with 1 ≤ m < 10, after rounding m
    int exponent = static_cast<int>(std::floor(std::log10(a)));
    std::string mantissa = plain(a / std::pow(10.0, exponent), digits);
    if (std::strtod(mantissa.c_str(), nullptr) >= 10.0) mantissa = plain(a / std::pow(10.0, ++exponent), digits);
    body = mantissa + " × 10" + superscript(exponent);
  }
  return (x < 0.0 ? kMinus : "") + body;
}

}  // namespace sim::describe

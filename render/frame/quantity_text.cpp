#include "render/frame/quantity_text.h"

#include <cmath>
#include <cstdio>

#include "sim/describe/number_text.h"

namespace render::frame {

std::string signedNumber(double x, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(x));
  // a value that rounds to zero has no sign to show
  const bool zero = std::string(buf).find_first_not_of("0.") == std::string::npos;
  return (x < 0.0 && !zero ? "\u2212" : "") + std::string(buf);
}

std::string timeToMs(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", t);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string numberText(double x, double zeroBelow) { return sim::describe::numberText(x, 3, zeroBelow); }

std::string quantityText(const std::string& name, double x, const std::string& unit, double zeroBelow) {
  return name + " = " + numberText(x, zeroBelow) + " " + unit;
}

std::string vectorText(const std::string& name, const sim::core::Vec2& v, const std::string& unit, double zeroBelow) {
  return name + " = (" + numberText(v.x(), zeroBelow) + ", " + numberText(v.y(), zeroBelow) + ") " + unit;
}

std::string vectorText(const std::string& name, const Eigen::Vector3d& v, const std::string& unit, double zeroBelow) {
  return name + " = (" + numberText(v.x(), zeroBelow) + ", " + numberText(v.y(), zeroBelow) + ", " +
         numberText(v.z(), zeroBelow) + ") " + unit;
}

}  // namespace render::frame

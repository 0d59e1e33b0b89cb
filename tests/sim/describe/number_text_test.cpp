// Numbers as a slide writes them (number_text.cpp): three significant digits in plain notation from
// 0.001 to 10,000, a power of ten outside, a true minus sign, 0 as "0", round-off below a
// tolerance as 0.
#include <doctest/doctest.h>

#include <cmath>

#include "sim/describe/number_text.h"

using sim::describe::numberText;

TEST_CASE("three significant digits in plain notation from 0.001 to 10,000") {
  CHECK(numberText(2.0) == "2.00");
  CHECK(numberText(0.5) == "0.500");
  CHECK(numberText(1.0 / 3.0) == "0.333");
  CHECK(numberText(3.515) == "3.52");  // 3.51499999… in binary: printf rounds the double once
  CHECK(numberText(12.345) == "12.3");
  CHECK(numberText(123.45) == "123");
  CHECK(numberText(1234.5) == "1230");
  CHECK(numberText(0.001) == "0.00100");
  CHECK(numberText(0.0012345) == "0.00123");
  CHECK(numberText(9984.0) == "9980");
  CHECK(numberText(-1.0 / 3.0) == "−0.333");
}

TEST_CASE("rounding that carries into a new digit keeps three digits") {
  CHECK(numberText(9.9996) == "10.0");
  CHECK(numberText(0.0099996) == "0.0100");
  CHECK(numberText(99.96) == "100");
  CHECK(numberText(0.99996) == "1.00");
}

TEST_CASE("outside [0.001, 10,000]: a power of ten with superscript digits") {
  CHECK(numberText(5.84e-13) == "5.84 × 10⁻¹³");
  CHECK(numberText(6.01e-06) == "6.01 × 10⁻⁶");
  CHECK(numberText(12345.0) == "1.23 × 10⁴");
  CHECK(numberText(9999.7) == "1.00 × 10⁴");
  CHECK(numberText(9999.0) == "1.00 × 10⁴");
  CHECK(numberText(-2.5e20) == "−2.50 × 10²⁰");
}

TEST_CASE("a true minus sign, no sign on zero, and round-off below the tolerance is 0") {
  CHECK(numberText(-2.0) == "\u22122.00");
  CHECK(numberText(-0.5) == "−0.500");
  CHECK(numberText(0.0) == "0");
  CHECK(numberText(-0.0) == "0");
  CHECK(numberText(5.84e-13, 3, 1e-9) == "0");
  CHECK(numberText(-5.84e-13, 3, 1e-9) == "0");
  CHECK(numberText(0.01, 3, 1e-9) == "0.0100");
  CHECK(numberText(NAN) == "nan");
  CHECK(numberText(-INFINITY) == "−∞");
  // no hyphen anywhere
  for (double x : {-1e-20, -1e-3, -0.5, -7.0, -1234.0, -1e9}) CHECK(numberText(x).find('-') == std::string::npos);
}

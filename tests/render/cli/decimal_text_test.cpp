// Numbers given on the command line (decimal_text.cpp): what std::stod refuses but is a number
// (a subnormal) is kept, what is not finite or not wholly a number is refused, and −0 reads as 0.
#include "render/cli/decimal_text.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using render::cli::decimalText;

TEST_CASE("a subnormal is a number: strtod's ERANGE on underflow is not a refusal") {
  const auto x = decimalText("1e-320");
  REQUIRE(x.has_value());
  CHECK(*x > 0.0);
  CHECK(*x < std::numeric_limits<double>::min());
  CHECK(std::fpclassify(*x) == FP_SUBNORMAL);
  // below the smallest subnormal: underflows to 0, still a number
  CHECK(decimalText("1e-400") == 0.0);
}

TEST_CASE("-0 reads as +0, so nothing named from it says 't-0'") {
  const auto x = decimalText("-0");
  REQUIRE(x.has_value());
  CHECK(*x == 0.0);
  CHECK_FALSE(std::signbit(*x));
  CHECK_FALSE(std::signbit(*decimalText("-0.0e5")));
}

TEST_CASE("an overflow, infinity and NaN are not numbers to use") {
  CHECK_FALSE(decimalText("1e400").has_value());
  CHECK_FALSE(decimalText("-1e400").has_value());
  CHECK_FALSE(decimalText("inf").has_value());
  CHECK_FALSE(decimalText("nan").has_value());
}

TEST_CASE("the whole text must be the number; blanks around it are allowed") {
  CHECK(decimalText(" 0.5 ") == 0.5);
  CHECK(decimalText("2.25") == 2.25);
  CHECK(decimalText("-3") == -3.0);
  CHECK_FALSE(decimalText("").has_value());
  CHECK_FALSE(decimalText("  ").has_value());
  CHECK_FALSE(decimalText("0.5s").has_value());
  CHECK_FALSE(decimalText("1,5").has_value());
  CHECK_FALSE(decimalText("x").has_value());
  CHECK_FALSE(decimalText(std::string("1\0"
                                      "5",
                                      3))
                  .has_value());
}

// A number given on the command line (--at 0.5,1e-320): the whole text read as a decimal, with
// what std::stod refuses but means a number kept. strtod reports ERANGE for a subnormal (1e-320)
// as for an overflow (1e400); only the overflow, which reads as ±∞, is not a number we can use.
#pragma once

#include <optional>
#include <string>

namespace render::cli {

// `text` (surrounding blanks allowed) as a finite double, −0 read as 0 (a name made from it must
// not say "t-0"); nullopt when it is not wholly a number or is not finite
std::optional<double> decimalText(const std::string& text);

}  // namespace render::cli

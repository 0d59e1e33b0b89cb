// A string as YAML reads it back inside a flow mapping ({body: NAME, ...}): plain when it is a
// plain word, else double-quoted with escapes, so that a pasted `expect` entry names its body.
#pragma once

#include <string>
#include <string_view>

namespace render::cli {

// "ball", "\"a, b\"", "\"null\"", "\"x: y\"", "\"\\x1b\""
std::string yamlScalar(std::string_view text);

}  // namespace render::cli

// A CSV field as RFC 4180 writes it: as it is, or in double quotes (its quotes doubled) when it holds
// a comma, a quote or a line break, so that a body named "a,b" keeps a trace's rows whole.
#pragma once

#include <string>
#include <string_view>

namespace render::jobs {

inline std::string csvField(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

}  // namespace render::jobs

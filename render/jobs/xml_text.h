// Text put into XML and HTML: the five markup characters escaped, and what no XML parser takes
// replaced by U+FFFD (a control character other than tab and line breaks, a byte that is not
// UTF-8), so that one odd body name or file name cannot make a whole JUnit file or page unreadable.
#pragma once

#include <string>
#include <string_view>

namespace render::jobs {

// `text` for an XML or HTML text node or a quoted attribute value (&#39; for ' is XML's too)
std::string escapeXml(std::string_view text);

// the length of the well-formed UTF-8 sequence at the start of `text`, or 0
size_t utf8Length(std::string_view text);

}  // namespace render::jobs

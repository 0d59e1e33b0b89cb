// One reader for the files rigidreel reads back (traces, a golden record's manifest, states, draw
// lists and baseline PNGs, a pack's order.txt and title.txt): opening never blocks (a FIFO or a
// device is refused at open, as is a folder), a file larger than its bound (read_limits.h) is
// refused before it is read and while it grows, and Ctrl-C is honoured between two pieces.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace render::jobs {

// the whole of the regular file `path`, at most `maxBytes`; `what` names it in messages ("trace",
// "golden manifest") and `remedy` says what to do ("record it again"). Throws UsageError (exit 2)
// naming the path for a file that is missing, unreadable, not a regular file or too large, and
// Interrupted when Ctrl-C comes while it reads
std::string readBounded(const std::string& path, size_t maxBytes, const std::string& what, const std::string& remedy);

// `text` without the UTF-8 byte order mark that some editors put at its start
std::string_view withoutBom(std::string_view text);

}  // namespace render::jobs

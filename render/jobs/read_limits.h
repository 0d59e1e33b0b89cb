// How much rigidreel reads back of the files it (or another simulator, or a course's CI) wrote: each
// bound in bytes, checked when the file is opened and again as it is read (README.md's Limits).
#pragma once

#include <cstddef>

namespace render::jobs {

// a trace CSV (`compare --trace`, `--overlay`, a golden record's trace.csv): about 2.5 million rows
// of one body (100 bytes a row), read into 0.45 GB at most (the text and 72 bytes a row)
inline constexpr size_t kMaxTraceBytes = size_t{256} << 20;
// a golden record's manifest.json, states.csv and each frame's draw list (a frame of 100,000 bodies
// is 15 MB of JSON)
inline constexpr size_t kMaxRecordFileBytes = size_t{64} << 20;
// a PNG read back (a golden record's baseline frame): an 8192 × 8192 frame, stored uncompressed, is 192 MiB
inline constexpr size_t kMaxPngBytes = size_t{256} << 20;
// a pack's order.txt and title.txt: a line per scene, one line
inline constexpr size_t kMaxListFileBytes = size_t{1} << 20;

}  // namespace render::jobs

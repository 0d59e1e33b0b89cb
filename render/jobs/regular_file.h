// Files the program reads (scene files, a pack's records, its videos and images) must be regular
// files: opening a FIFO blocks until a writer comes, and a device or a socket never ends.
#pragma once

#include <string>

namespace render::jobs {

// "" when `path` is a regular file (after symlinks) or does not exist; else what it is instead, as
// "is a FIFO (named pipe), not a regular file"
std::string notRegularFile(const std::string& path);

}  // namespace render::jobs

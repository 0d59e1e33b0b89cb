// SHA-256 of a file, to tell in a golden record's manifest which scene file it was recorded from.
#pragma once

#include <string>

namespace render::golden {

// the hex digest of `bytes`
std::string sha256(const std::string& bytes);
// the hex digest of the file's contents; throws std::runtime_error naming a file it cannot read
std::string fileSha256(const std::string& path);

}  // namespace render::golden

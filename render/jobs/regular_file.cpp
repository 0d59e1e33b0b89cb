#include "render/jobs/regular_file.h"

#include <filesystem>

namespace render::jobs {

std::string notRegularFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  switch (fs::status(path, error).type()) {
    case fs::file_type::regular:
    case fs::file_type::not_found:
    case fs::file_type::none: return "";
    case fs::file_type::directory: return "is a directory, not a regular file";
    case fs::file_type::fifo: return "is a FIFO (named pipe), not a regular file";
    case fs::file_type::socket: return "is a socket, not a regular file";
    default: return "is a device, not a regular file";
  }
}

}  // namespace render::jobs

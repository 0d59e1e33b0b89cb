// A scratch folder of a test, unique to the process and removed when the test ends: the files a
// reader is given, made in the test itself.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace support {

struct ScratchFolder {
  std::filesystem::path dir;
  explicit ScratchFolder(const std::string& test)
      : dir(std::filesystem::temp_directory_path() / ("rigidreel_" + test + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~ScratchFolder() { std::filesystem::remove_all(dir); }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  // the path of `name` in the folder
  std::string at(const std::string& name) const { return (dir / name).string(); }
};

}  // namespace support

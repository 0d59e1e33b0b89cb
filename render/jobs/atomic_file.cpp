#include "render/jobs/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "render/jobs/stale_parts.h"

namespace render::jobs {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temporary_(partName(path_)) {
  removeStaleParts(path_);
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(path_ + ": cannot write here (" + std::strerror(errno) + "); choose a writable path");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::remove(temporary_.c_str());
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error(path_ + ": could not finish writing (" + std::strerror(errno) + ")");
  committed_ = true;
}

namespace fs = std::filesystem;

StagedDirectory::StagedDirectory(const std::string& final) : final_(final) {
  const fs::path path(final);
  // ".<name>.part-<pid>", appended piece by piece: g++ 12 warns of overlapping copies in "." + name
  std::string name = ".";
  name += path.filename().string();
  name += ".part-" + std::to_string(::getpid());
  staging_ = (path.parent_path() / name).string();
  // the folders of runs killed outright (SIGKILL) before they could remove them
  removeStaleParts(final);
  fs::remove_all(staging_);
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(staging_, ignored);
}

void StagedDirectory::commit() {
  fs::remove_all(final_);
  fs::rename(staging_, final_);
  committed_ = true;
}

}  // namespace render::jobs

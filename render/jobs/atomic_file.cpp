#include "render/jobs/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "render/jobs/interrupt.h"
#include "render/jobs/output_rules.h"
#include "render/jobs/stale_parts.h"

namespace render::jobs {

namespace fs = std::filesystem;

namespace {

// /dev/stdout is a link to /proc/self/fd/1, which links to whatever standard output is, a regular
// file too: what is named there is a stream to write to, not a file to replace
bool streamName(const std::string& path) { return path.starts_with("/dev/") || path.starts_with("/proc/"); }

}  // namespace

std::string finalTarget(const std::string& path) {
  std::error_code error;
  if (streamName(path) || !fs::is_symlink(fs::symlink_status(path, error))) return path;
  // a dangling link's target does not exist: weakly_canonical resolves what does
  const fs::path target = fs::weakly_canonical(path, error);
  return error ? path : target.string();
}

bool writtenThrough(const std::string& path) {
  if (streamName(path)) return true;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  return fs::exists(status) && !fs::is_regular_file(status);
}

AtomicFile::AtomicFile(std::string path)
    : path_(finalTarget(path)), temporary_(partName(path_)), through_(writtenThrough(path_)) {
  if (through_) {
    // a device or a FIFO: opened as it is (no truncation of what is not a file), written as it goes
    temporary_ = path_;
    out_.open(path_, std::ios::binary | std::ios::out);
  } else {
    removeStaleParts(path_);
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
  }
  if (!out_) {
    const int error = errno;
    // Ctrl-C while a FIFO waits for its reader: open(2) fails with EINTR, and the run is interrupted
    checkInterrupted();
    throw std::runtime_error(path + ": cannot write here (" + std::strerror(error) + "); choose a writable path");
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  if (!through_) std::remove(temporary_.c_str());
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  const int written = errno;
  out_.close();
  const bool closed = static_cast<bool>(out_);
  if (!ok || !closed) {
    errno = ok ? errno : written;
    throw std::runtime_error(path_ + ": could not finish writing (" + std::strerror(errno) + ")");
  }
  if (!through_ && std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error(path_ + ": could not finish writing (" + std::strerror(errno) + ")");
  committed_ = true;
}

StagedDirectory::StagedDirectory(const std::string& final, const std::string& writer)
    : final_(finalTarget(withoutTrailingSlash(final))) {
  const fs::path path(final_);
  // ".<name>.part-<pid>", appended piece by piece: g++ 12 warns of overlapping copies in "." + name
  std::string name = ".";
  name += partPrefix(path.filename().string());
  name += ".part-" + std::to_string(::getpid());
  staging_ = (path.parent_path() / name).string();
  // the folders of runs killed outright (SIGKILL) before they could remove them
  removeStaleParts(final_);
  fs::remove_all(staging_);
  fs::create_directories(staging_);
  if (!writer.empty()) std::ofstream(fs::path(staging_) / kFolderMarker) << writer << '\n';
}

StagedDirectory::~StagedDirectory() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(staging_, ignored);
}

namespace {

[[noreturn]] void cannotPublish(const std::string& final) {
  throw std::runtime_error(final + ": could not put the new folder in place (" + std::strerror(errno) + ")");
}

}  // namespace

// Two runs may publish the same folder at once (two renders of one scene into one -o). Removing the
// old folder and then renaming the new one over it left a window in which the other run's rename
// failed (ENOTEMPTY) or its remove_all deleted files under the other's feet; here the folder under
// the final name is at every instant a whole one. renameat2 (Linux 3.15, glibc 2.28):
// RENAME_NOREPLACE publishes the first folder, RENAME_EXCHANGE swaps the new folder with the old
// one in one step, after which the old one sits under this run's own ".part-<pid>" name, which no
// other run touches.
void StagedDirectory::commit() {
  // a few rounds: another run may publish or swap between two of these calls
  for (int round = 0; round < 100; ++round) {
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_NOREPLACE) == 0) {
      committed_ = true;
      return;
    }
    if (errno == EINVAL) return commitWithoutExchange();  // a file system without renameat2's flags
    if (errno != EEXIST) cannotPublish(final_);
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) == 0) {
      committed_ = true;
      std::error_code ignored;
      fs::remove_all(staging_, ignored);  // the old folder, under our name now
      return;
    }
    if (errno == EINVAL) return commitWithoutExchange();
    // ENOENT: the final name vanished between the two calls; try again
    if (errno != ENOENT) cannotPublish(final_);
  }
  cannotPublish(final_);
}

// Without an exchange: the old folder renamed aside to this run's own name first, then the new one
// renamed into the free name, again if another run took it in between. Readers may see no folder
// for an instant, but no run fails and none removes another's files.
void StagedDirectory::commitWithoutExchange() {
  const std::string aside = staging_ + "-old";
  std::error_code ignored;
  for (int round = 0; round < 100; ++round) {
    fs::remove_all(aside, ignored);
    if (std::rename(final_.c_str(), aside.c_str()) != 0 && errno != ENOENT) cannotPublish(final_);
    if (std::rename(staging_.c_str(), final_.c_str()) == 0) {
      committed_ = true;
      fs::remove_all(aside, ignored);
      return;
    }
    if (errno != ENOTEMPTY && errno != EEXIST) cannotPublish(final_);
  }
  cannotPublish(final_);
}

}  // namespace render::jobs

// An output file written under a temporary name and renamed into place only when complete, so a
// failed or interrupted run never leaves a half file nor clobbers the previous good one. A path that
// is not a regular file (a device, a FIFO, a socket: /dev/stdout, /dev/null) is written through, and
// a symlink's target is the file replaced: what the user named is never replaced by a regular file.
#pragma once

#include <fstream>
#include <string>

namespace render::jobs {

class AtomicFile {
 public:
  // throws std::runtime_error naming the path when it cannot be created
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  // the file written until commit: the temporary, or the path itself when written through
  const std::string& temporaryPath() const { return temporary_; }
  // flush, close and rename over the final path; throws std::runtime_error on failure
  void commit();

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
  bool through_ = false;  // written in place: nothing to rename, nothing to remove
};

// the path written in place of `path`: a symlink's final target (so the link stays a link), else
// `path` itself
std::string finalTarget(const std::string& path);
// whether `path` exists and is not a regular file (after symlinks): written through, not replaced
bool writtenThrough(const std::string& path);

// a directory filled under a temporary name (".<name>.part-<pid>" beside it) and swapped with the
// old one when complete, atomically, so that two runs publishing the same folder at once both
// succeed and it is always one run's whole folder (video frames as PNG). A symlink's target is the
// folder replaced (the link kept); with a `writer`, the folder carries its marker (output_rules.h)
class StagedDirectory {
 public:
  explicit StagedDirectory(const std::string& final, const std::string& writer = "");
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  std::string path() const { return staging_; }
  // throws std::runtime_error naming the folder when it cannot be put in place
  void commit();

 private:
  void commitWithoutExchange();
  std::string final_, staging_;
  bool committed_ = false;
};

}  // namespace render::jobs

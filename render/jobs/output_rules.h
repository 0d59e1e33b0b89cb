// One rule for every output of a run, checked before any work: a path an output would write is
// refused (UsageError, exit 2, naming the option, the path and what to do) when it is or holds an
// input of the run, when it is a folder holding files the command did not write, when it cannot be
// created, or when another output of the run would write the same path.
#pragma once

#include <string>
#include <vector>

namespace render::jobs {

// the file a folder replaced whole carries, naming the command that wrote it ("golden report")
inline constexpr const char* kFolderMarker = ".rigidreel";

struct PlannedOutput {
  enum class Kind {
    File,    // a file replaced (written under a temporary name, renamed)
    Folder,  // a folder replaced whole: new, empty, or marked by `writer`
    Into,    // a folder files are written into, nothing else in it touched
  };
  std::string path;
  std::string option;  // "-o", "--report"
  Kind kind = Kind::File;
  std::string writer = {};  // Folder: the command whose marker it may carry ("golden record")
  std::string what = {};    // what is written there, for two outputs that collide ("the record of x.yaml")
};

// a file or folder the run reads
struct RunInput {
  std::string path;
  std::string what = "the scene file";  // "the --overlay trace", "the golden record"
};

// throws UsageError for the first output that breaks the rule
void refuseOutputs(const std::vector<PlannedOutput>& outputs, const std::vector<RunInput>& inputs);

// `path` without the trailing slashes shell completion adds ("out/" is "out"; "/" stays)
std::string withoutTrailingSlash(std::string path);

}  // namespace render::jobs

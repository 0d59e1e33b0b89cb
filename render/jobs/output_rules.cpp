#include "render/jobs/output_rules.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "render/jobs/exit_status.h"

namespace render::jobs {

namespace fs = std::filesystem;
using Kind = PlannedOutput::Kind;

namespace {

// the path as the file system resolves it (links followed, "." and ".." gone), also for what does
// not exist yet
std::string resolved(const std::string& path) {
  std::error_code error;
  const fs::path p = fs::weakly_canonical(withoutTrailingSlash(path), error);
  return error ? fs::absolute(path).lexically_normal().string() : p.string();
}

// whether `path` is `folder` or lies inside it (both resolved)
bool within(const std::string& path, const std::string& folder) {
  if (path == folder) return true;
  const std::string prefix = folder.ends_with('/') ? folder : folder + "/";
  return path.starts_with(prefix);
}

bool streamName(const std::string& path) { return path.starts_with("/dev/") || path.starts_with("/proc/"); }

[[noreturn]] void refuse(const PlannedOutput& o, const std::string& why) {
  throw UsageError(o.option + ": " + o.path + " " + why);
}

void refuseInputs(const PlannedOutput& o, const std::vector<RunInput>& inputs) {
  const std::string out = resolved(o.path);
  for (const RunInput& in : inputs) {
    if (in.path.empty()) continue;
    const std::string read = resolved(in.path);
    if (read == out) refuse(o, "is " + in.what + " this run reads; choose another path to write");
    // a folder replaced whole takes everything inside it along
    if (o.kind == Kind::Folder && within(read, out))
      refuse(o, "holds " + in.what + " " + in.path +
                    ", which this run reads and the new folder would replace; choose another folder");
  }
}

void refuseWrongKind(const PlannedOutput& o) {
  std::error_code error;
  const fs::file_status s = fs::status(withoutTrailingSlash(o.path), error);
  if (!fs::exists(s)) return;
  if (o.kind == Kind::File && fs::is_directory(s)) refuse(o, "is a folder; name a file to write");
  if (o.kind != Kind::File && !fs::is_directory(s)) refuse(o, "is not a folder; choose a new folder to write");
}

// the nearest folder that exists on the way to `path`, where it would be created
fs::path nearestExisting(fs::path p) {
  std::error_code error;
  while (!p.empty() && !fs::exists(fs::symlink_status(p, error))) {
    if (p == p.parent_path()) break;
    p = p.parent_path();
  }
  return p.empty() ? fs::path(".") : p;
}

void refuseUncreatable(const PlannedOutput& o) {
  const fs::path p(withoutTrailingSlash(o.path));
  if (o.kind == Kind::File && streamName(o.path)) return;
  // a file or a folder replaced is renamed into its parent; a folder written into, into itself
  std::error_code error;
  const bool exists = fs::exists(fs::status(p, error));
  const fs::path where = o.kind == Kind::Into && exists ? p : nearestExisting(p.has_parent_path() ? p.parent_path() : ".");
  if (!fs::is_directory(fs::status(where, error)))
    refuse(o, "cannot be created: " + where.string() + " is not a folder; choose a writable path");
  if (::access(where.c_str(), W_OK | X_OK) != 0)
    refuse(o, "cannot be created in " + where.string() + " (" + std::strerror(errno) + "); choose a writable path");
}

// the folder's marker names `writer`; records made before markers carry their manifest instead
bool markedBy(const fs::path& folder, const std::string& writer) {
  std::ifstream marker(folder / kFolderMarker);
  std::string line;
  if (std::getline(marker, line) && line == writer) return true;
  if (writer != "golden record") return false;
  std::ifstream manifest(folder / "manifest.json");
  char start[20] = {};
  manifest.read(start, sizeof start);
  return std::string(start, sizeof start) == "{\"rigidreel_version\"";
}

void refuseForeignFolder(const PlannedOutput& o) {
  if (o.kind != Kind::Folder) return;
  const fs::path p(withoutTrailingSlash(o.path));
  std::error_code error;
  if (!fs::is_directory(fs::status(p, error)) || fs::is_empty(p, error) || markedBy(p, o.writer)) return;
  std::string some;
  int shown = 0;
  for (fs::directory_iterator it(p, error), end; !error && it != end && shown < 3; it.increment(error), ++shown)
    some += (shown ? ", " : "") + it->path().filename().string();
  refuse(o, "holds files " + o.writer + " did not write (" + some +
                "), which the new folder would replace; choose a new or empty folder, or move them away first");
}

// two outputs at one path, or a file inside a folder replaced whole
void refuseShared(const std::vector<PlannedOutput>& outputs) {
  for (size_t j = 0; j < outputs.size(); ++j)
    for (size_t i = 0; i < j; ++i) {
      const PlannedOutput &a = outputs[i], &b = outputs[j];
      if (a.path.empty() || b.path.empty()) continue;
      const std::string pa = resolved(a.path), pb = resolved(b.path);
      const bool inside = (a.kind == Kind::Folder && within(pb, pa)) || (b.kind == Kind::Folder && within(pa, pb));
      if (pa != pb && !inside) continue;
      if (a.option == b.option && !a.what.empty())
        refuse(b, "would hold both " + a.what + " and " + b.what + "; give them distinct names");
      refuse(b, "is also where " + a.option + " writes; choose distinct paths");
    }
}

}  // namespace

std::string withoutTrailingSlash(std::string path) {
  while (path.size() > 1 && path.ends_with('/')) path.pop_back();
  return path;
}

void refuseOutputs(const std::vector<PlannedOutput>& outputs, const std::vector<RunInput>& inputs) {
  for (const PlannedOutput& o : outputs) {
    if (o.path.empty()) continue;
    refuseInputs(o, inputs);
    refuseWrongKind(o);
    refuseForeignFolder(o);
    refuseUncreatable(o);
  }
  refuseShared(outputs);
}

}  // namespace render::jobs

#include "render/cli/scene_order.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "render/jobs/bounded_read.h"
#include "render/jobs/read_limits.h"
#include "sim/yaml/scene_error.h"

namespace render::cli {
namespace fs = std::filesystem;

namespace {

struct Entry {
  std::string stem;  // the file name without ".yaml"
  int line = 0;
};

// order.txt's entries, in order; none when there is no order.txt
std::vector<Entry> readOrder(const fs::path& path) {
  std::vector<Entry> entries;
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return entries;
  std::istringstream in(std::string(render::jobs::withoutBom(render::jobs::readBounded(
      path.string(), render::jobs::kMaxListFileBytes, "scene order", "make it a text file of scene names, one a line"))));
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    const size_t first = text.find_first_not_of(" \t\r"), last = text.find_last_not_of(" \t\r");
    if (first == std::string::npos) continue;
    std::string name = text.substr(first, last - first + 1);
    if (name.ends_with(".yaml")) name.resize(name.size() - 5);
    entries.push_back({name, line});
  }
  return entries;
}

std::string stemOf(const std::string& file) { return fs::path(file).stem().string(); }

}  // namespace

std::vector<std::string> orderedSceneFiles(const std::string& folder, std::vector<std::string> found) {
  std::sort(found.begin(), found.end());
  const fs::path path = fs::path(folder) / kOrderName;
  const std::vector<Entry> entries = readOrder(path);
  std::vector<std::string> ordered;
  for (const Entry& e : entries) {
    const auto at = std::find_if(found.begin(), found.end(), [&](const std::string& f) { return stemOf(f) == e.stem; });
    if (at == found.end()) {
      const bool twice = std::any_of(ordered.begin(), ordered.end(), [&](const std::string& f) { return stemOf(f) == e.stem; });
      throw sim::yaml::SceneError(path.string(), e.line, 1,
                                  twice
                                      ? "'" + e.stem + "' is listed twice; list each scene once"
                                      : "no scene file '" + e.stem + ".yaml' in " + folder + "; list the folder's *.yaml files");
    }
    ordered.push_back(*at);
    found.erase(at);
  }
  ordered.insert(ordered.end(), found.begin(), found.end());
  return ordered;
}

int orderInFolder(const std::string& file) {
  const std::vector<Entry> entries = readOrder(fs::path(file).parent_path() / kOrderName);
  for (size_t i = 0; i < entries.size(); ++i)
    if (entries[i].stem == stemOf(file)) return static_cast<int>(i) + 1;
  return 0;
}

}  // namespace render::cli

#include "render/cli/lecture_summary.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace render::cli {

namespace {

std::string padded(std::string s, size_t width, bool right = false) {
  if (s.size() < width) s.insert(right ? 0 : s.size(), width - s.size(), ' ');
  return s;
}

}  // namespace

std::string secondsText(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", s);
  return buf;
}

std::string indented(const std::string& text) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out += "  " + line + "\n";
  return out;
}

void printLectureSummary(const std::vector<SceneResult>& results, double wallSeconds, size_t parallel, bool messagesShown,
                         bool page, std::ostream& out, std::ostream& errors) {
  size_t nameWidth = 5;
  for (const SceneResult& r : results) nameWidth = std::max(nameWidth, r.scene.size());
  out << padded("scene", nameWidth) << "  status  outputs  seconds  files\n";
  size_t outputs = 0, failed = 0;
  for (const SceneResult& r : results) {
    std::string files;
    for (const std::string& p : r.outputs) {
      if (!files.empty()) files += ' ';
      files += std::filesystem::path(p).filename().string();
    }
    out << padded(r.scene, nameWidth) << "  " << padded(r.ok ? "ok" : "FAILED", 6) << "  "
        << padded(std::to_string(r.outputs.size()), 7, true) << "  " << padded(secondsText(r.seconds), 7, true) << "  " << files
        << '\n';
    outputs += r.outputs.size();
    failed += r.ok ? 0 : 1;
  }
  if (page) ++outputs;
  out << "total: " << results.size() << " scenes, " << outputs << " outputs" << (page ? " with the page" : "") << ", "
      << secondsText(wallSeconds) << " s wall time (" << parallel << " at a time)";
  if (failed) out << "; " << failed << " failed";
  out << '\n';
  if (messagesShown) return;
  for (const SceneResult& r : results)
    if (!r.ok) errors << "failed: " << r.scene << " (" << r.file << "):\n" << indented(r.message);
}

std::vector<std::string> wroteLines(const std::string& output) {
  std::vector<std::string> paths;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("wrote ", 0) == 0) paths.push_back(line.substr(6));
  return paths;
}

}  // namespace render::cli

// The lines that open every CSV the benches write (render/bench/README.md): `#` comments naming the
// command, the machine, the date and the commit, so that a committed table says where its numbers
// come from. Then the header row and the rows; the file is written whole under a temporary name
// and renamed (render/jobs/atomic_file.h), so an interrupted bench never leaves half a table.
#pragma once

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/jobs/atomic_file.h"

namespace bench {

// the lines of a command's output, without their newlines (none when it fails)
inline std::vector<std::string> commandLines(const char* command) {
  std::vector<std::string> lines;
  if (FILE* pipe = ::popen(command, "r")) {
    std::array<char, 512> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) {
      std::string line = buffer.data();
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
      lines.push_back(line);
    }
    ::pclose(pipe);
  }
  return lines;
}

// the commit checked out, and the tracked files changed since, if any, by name: a change to the
// docs alone does not change what was measured, and a reader can tell
inline std::string commitText() {
  const std::vector<std::string> head = commandLines("git rev-parse --short=12 HEAD 2>/dev/null");
  if (head.empty()) return "unknown (not a git checkout)";
  std::string text = head.front();
  const std::vector<std::string> changed = commandLines("git status --porcelain --untracked-files=no 2>/dev/null");
  for (size_t i = 0; i < changed.size() && i < 8; ++i)
    text += (i == 0 ? " with uncommitted changes to " : ", ") + (changed[i].size() > 3 ? changed[i].substr(3) : changed[i]);
  if (changed.size() > 8) text += " and " + std::to_string(changed.size() - 8) + " more";
  return text;
}

// the value of `key` in a file of "key<separator>value" lines, quotes and spaces trimmed
inline std::string fileValue(const std::string& path, const std::string& key, char separator) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    const size_t at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string value = line.substr(at + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t' || value.front() == '"')) value.erase(0, 1);
    while (!value.empty() && (value.back() == ' ' || value.back() == '"')) value.pop_back();
    return value;
  }
  return "unknown";
}

// "# command: ...", "# machine: <cpu model>, <n> cores, <os>", "# date: ...", "# commit: ...",
// "# load: ..." (the 1-minute load average as the bench started: the machine may be shared)
inline std::string csvPreamble(int argc, char** argv) {
  std::string command;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i > 0) command += ' ';
    command += arg.find_first_of(" \t'\"") == std::string::npos ? arg : "'" + arg + "'";
  }
  const long cores = ::sysconf(_SC_NPROCESSORS_ONLN);
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
  double load[1] = {0.0};
  const bool haveLoad = ::getloadavg(load, 1) == 1;
  char loadText[32] = "unknown";
  if (haveLoad) std::snprintf(loadText, sizeof loadText, "%.2f", load[0]);
  return "# command: " + command + "\n# machine: " + fileValue("/proc/cpuinfo", "model name", ':') + ", " +
         std::to_string(cores) + " cores, " + fileValue("/etc/os-release", "PRETTY_NAME", '=') + "\n# date: " + date +
         "\n# commit: " + commitText() + "\n# load: " + loadText + " (1-minute load average as the bench started)\n";
}

// `text` written to `path` whole, its folder made if missing: under a temporary name, then renamed
// (throws std::runtime_error)
inline void writeWhole(const std::string& path, const std::string& text) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder);
  render::jobs::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

// `text` written whole to `path`, and said on stdout; false, with why on stderr, when it cannot be
inline bool writeCsv(const std::string& path, const std::string& text) {
  try {
    writeWhole(path, text);
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return false;
  }
  std::cout << "wrote " << path << '\n';
  return true;
}

}  // namespace bench

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

#include "render/jobs/atomic_file.h"

namespace bench {

// the first line of a command's output, without its newline ("" when it fails)
inline std::string commandLine(const char* command) {
  std::string text;
  if (FILE* pipe = ::popen(command, "r")) {
    std::array<char, 256> buffer{};
    if (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) text = buffer.data();
    ::pclose(pipe);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
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
  std::string commit = commandLine("git rev-parse --short=12 HEAD 2>/dev/null");
  if (commit.empty()) commit = "unknown (not a git checkout)";
  else if (!commandLine("git status --porcelain --untracked-files=no 2>/dev/null").empty()) commit += " with uncommitted changes";
  double load[1] = {0.0};
  const bool haveLoad = ::getloadavg(load, 1) == 1;
  char loadText[32] = "unknown";
  if (haveLoad) std::snprintf(loadText, sizeof loadText, "%.2f", load[0]);
  return "# command: " + command + "\n# machine: " + fileValue("/proc/cpuinfo", "model name", ':') + ", " +
         std::to_string(cores) + " cores, " + fileValue("/etc/os-release", "PRETTY_NAME", '=') + "\n# date: " + date +
         "\n# commit: " + commit + "\n# load: " + loadText + " (1-minute load average as the bench started)\n";
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

// The end of `rigidreel lecture`: a table of the scenes (status, outputs, seconds, the files),
// the total wall time, and each failed scene with its message.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace render::cli {

struct SceneResult {
  std::string scene;  // the scene's name
  std::string file;   // its file
  bool ok = false;
  std::vector<std::string> outputs;  // the paths it wrote
  double seconds = 0;
  std::string message;  // why it failed: its standard error, or how it ended
};

// the table and the total on `out` (the outputs counting the page when `page` was written); the
// failed scenes, each with its message, on `errors` (unless `messagesShown`: a scene run in this
// process has said why already)
void printLectureSummary(const std::vector<SceneResult>& results, double wallSeconds, size_t parallel, bool messagesShown,
                         bool page, std::ostream& out, std::ostream& errors);

// "  " before each line of `text`, which ends with a newline (when not empty)
std::string indented(const std::string& text);

// seconds to two decimals: "4.21"
std::string secondsText(double seconds);

// the paths in a job's standard output: its lines "wrote PATH"
std::vector<std::string> wroteLines(const std::string& output);

}  // namespace render::cli

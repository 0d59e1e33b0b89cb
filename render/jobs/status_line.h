// One line of status on standard error, redrawn in place with '\r', and only on a terminal: a pipe
// or a file (scripts, tests, logs) never sees it, so what they read stays the same.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace render::jobs {

class StatusLine {
 public:
  using Duration = std::chrono::steady_clock::duration;
  // `enabled` false (--quiet) or `out` not a terminal: nothing is drawn. The first draw is due after
  // `delay` (a short run shows nothing), each later one `interval` after the last.
  StatusLine(bool enabled, Duration delay, Duration interval, std::FILE* out = stderr);
  ~StatusLine();
  StatusLine(const StatusLine&) = delete;
  StatusLine& operator=(const StatusLine&) = delete;

  bool enabled() const { return enabled_; }
  bool drawn() const { return drawn_; }
  // enabled, and `delay` since the start and `interval` since the last draw have passed
  bool due() const;
  // the line replaced by `text`
  void draw(const std::string& text);
  // end the line: kept (what is printed next starts below it) or cleared; nothing is drawn after
  void keep();
  void erase();
  // seconds since the start
  double elapsed() const;

 private:
  bool enabled_;
  Duration delay_, interval_;
  std::FILE* out_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, lastDrawn_;
};

}  // namespace render::jobs

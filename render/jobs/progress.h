// A progress bar on standard error, drawn only when standard error is a terminal.
#pragma once

#include <chrono>
#include <string>

namespace render::jobs {

class Progress {
 public:
  // `enabled` false (--quiet) or a standard error that is not a terminal: nothing is drawn
  Progress(std::string what, long total, bool enabled);
  ~Progress();
  void update(long done);
  // end the bar's line (so that what is printed next starts on its own); the destructor does it too
  void finish();
  // seconds since the start
  double elapsed() const;

 private:
  std::string what_;
  long total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDrawn_;
};

}  // namespace render::jobs

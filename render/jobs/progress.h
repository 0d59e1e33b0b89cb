// A progress bar of frames on standard error, drawn only when standard error is a terminal.
#pragma once

#include <string>

#include "render/jobs/status_line.h"

namespace render::jobs {

class Progress {
 public:
  // `enabled` false (--quiet) or a standard error that is not a terminal: nothing is drawn
  Progress(std::string what, long total, bool enabled);
  void update(long done);
  // end the bar's line (so that what is printed next starts on its own); the destructor does it too
  void finish() { line_.keep(); }
  ~Progress() { finish(); }
  // seconds since the start
  double elapsed() const { return line_.elapsed(); }

 private:
  std::string what_;
  long total_;
  StatusLine line_;
};

}  // namespace render::jobs

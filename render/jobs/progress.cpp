#include "render/jobs/progress.h"

#include <unistd.h>

#include <cstdio>

namespace render::jobs {

Progress::Progress(std::string what, long total, bool enabled)
    : what_(std::move(what)), total_(total), enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::finish() {
  if (drawn_) std::fputc('\n', stderr);
  drawn_ = false;
  enabled_ = false;
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // ten redraws a second are enough for the eye, and the last frame always shows
  if (drawn_ && done < total_ && now - lastDrawn_ < std::chrono::milliseconds(100)) return;
  lastDrawn_ = now;
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? static_cast<int>(kWidth * done / total_) : kWidth;
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(kWidth - filled), '-');
  const double seconds = elapsed();
  std::fprintf(stderr, "\r%s [%s] %ld/%ld frames, %.1f frames/s ", what_.c_str(), bar.c_str(), done, total_,
               seconds > 0.0 ? done / seconds : 0.0);
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace render::jobs

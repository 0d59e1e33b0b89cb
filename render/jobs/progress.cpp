#include "render/jobs/progress.h"

#include <chrono>
#include <cstdio>

namespace render::jobs {

// ten redraws a second are enough for the eye
Progress::Progress(std::string what, long total, bool enabled)
    : what_(std::move(what)), total_(total), line_(enabled, {}, std::chrono::milliseconds(100)) {}

void Progress::update(long done) {
  // the last frame always shows
  if (!line_.enabled() || (!line_.due() && done < total_)) return;
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? static_cast<int>(kWidth * done / total_) : kWidth;
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(kWidth - filled), '-');
  const double seconds = elapsed();
  char counts[96];
  std::snprintf(counts, sizeof counts, "] %ld/%ld frames, %.1f frames/s ", done, total_, seconds > 0.0 ? done / seconds : 0.0);
  line_.draw(what_ + " [" + bar + counts);
}

}  // namespace render::jobs

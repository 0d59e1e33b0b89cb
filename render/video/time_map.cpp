#include "render/video/time_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/jobs/exit_status.h"
#include "render/jobs/json_writer.h"
#include "sim/core/step_limit.h"

namespace render::video {
using namespace render::scene;

std::vector<SlowWindow> mergeWindows(std::vector<SlowWindow> windows, double duration) {
  for (SlowWindow& w : windows) w.from = std::max(0.0, w.from), w.to = std::min(duration, w.to);
  std::erase_if(windows, [](const SlowWindow& w) { return !(w.to > w.from); });
  std::sort(windows.begin(), windows.end(), [](const SlowWindow& a, const SlowWindow& b) { return a.from < b.from; });
  std::vector<SlowWindow> merged;
  for (const SlowWindow& w : windows) {
    if (!merged.empty() && w.from <= merged.back().to) {
      merged.back().to = std::max(merged.back().to, w.to);
      merged.back().factor = std::max(merged.back().factor, w.factor);
    } else {
      merged.push_back(w);
    }
  }
  return merged;
}

TimeMap::TimeMap(double duration, double titleCard, std::vector<SlowWindow> windows, double answerCard)
    : duration_(duration), titleCard_(titleCard), answerCard_(answerCard), windows_(mergeWindows(std::move(windows), duration)) {
  length_ = titleCard_ + duration_ + answerCard_;
  for (const SlowWindow& w : windows_) length_ += (w.factor - 1.0) * (w.to - w.from);
}

long TimeMap::frameCount(double fps) const {
  // the tolerance keeps a length of exactly k / fps at k frames despite round-off
  const double frames = std::ceil(length_ * fps - 1e-9);
  // bounded before the conversion: a count past a long's range is undefined behavior
  if (!(frames <= kMaxFrames)) {
    const auto [count, limit] = sim::core::distinctCounts(frames, kMaxFrames);
    std::ostringstream m;
    m << "the video would have " << count << " frames (" << length_ << " s at " << fps << " fps), more than the limit of "
      << limit << "; shorten the scene's duration, title_card, answer_card or slow_motion (or --duration), or lower --fps";
    throw render::jobs::UsageError(m.str());
  }
  // fewer frames than one a video length: ffmpeg fails, or writes one frame shown for hours
  if (length_ > 0.0 && length_ * fps < 1.0 - 1e-9) {
    using render::jobs::formatNumber;
    throw render::jobs::UsageError("at " + formatNumber(fps) + " fps a video of " + formatNumber(length_) +
                                   " s has less than one frame; give at least " + formatNumber(1.0 / length_) +
                                   " fps (one frame a video length)");
  }
  return std::max(1L, static_cast<long>(frames));
}

double TimeMap::simTime(double u) const {
  const double v = u - titleCard_;
  if (v <= 0.0) return 0.0;
  // walk the pieces: normal pace up to each window, then the window slowed
  double t = 0.0, start = 0.0;
  for (const SlowWindow& w : windows_) {
    if (v < start + (w.from - t)) return t + (v - start);
    start += w.from - t;
    const double slowed = w.factor * (w.to - w.from);
    if (v < start + slowed) return w.from + (v - start) / w.factor;
    start += slowed;
    t = w.to;
  }
  return std::min(duration_, t + (v - start));
}

double TimeMap::factorAt(double t) const {
  for (const SlowWindow& w : windows_)
    if (t >= w.from && t < w.to) return w.factor;
  return 1.0;
}

TimeMap timeMapFor(const render::scene::RenderDef& render, const std::vector<double>& impactTimes, double duration) {
  std::vector<SlowWindow> windows;
  for (const render::scene::SlowMotionDef& s : render.slowMotion) {
    if (s.window > 0.0)
      for (double t : impactTimes) windows.push_back({t - 0.5 * s.window, t + 0.5 * s.window, s.factor});
    else windows.push_back({s.from, s.to, s.factor});
  }
  return TimeMap(duration, render.titleCard, std::move(windows), render.poll.answerCard);
}

}  // namespace render::video

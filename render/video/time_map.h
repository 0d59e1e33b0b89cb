// Video time to simulation time: an opening title card (simulation time 0 throughout), then the run
// at its own pace, except in slow-motion windows where the video runs `factor` times slower, then
// a closing answer card (simulation time `duration` throughout). The map
// is piecewise linear and monotone; frame k shows the simulation time that video time k / fps maps to,
// so frames still land on exact simulation times, just closer together where the video is slowed.
#pragma once

#include <optional>
#include <vector>

#include "render/scene/render_def.h"

namespace render::video {

// simulation times [from, to) shown `factor` times slower
struct SlowWindow {
  double from = 0.0, to = 0.0, factor = 1.0;
  bool operator==(const SlowWindow&) const = default;
};

// the windows sorted, clipped to [0, duration], empty ones dropped, and those that overlap or touch
// merged into one at the larger factor (so an impact inside another's window is not sped up)
std::vector<SlowWindow> mergeWindows(std::vector<SlowWindow> windows, double duration);

class TimeMap {
 public:
  // the identity over [0, duration] when there is no card and no window
  explicit TimeMap(double duration, double titleCard = 0.0, std::vector<SlowWindow> windows = {}, double answerCard = 0.0);

  // title card + the duration stretched by the windows + answer card, s
  double videoLength() const { return length_; }
  // frames at k / fps for every k / fps < videoLength (at least one); throws UsageError past
  // kMaxFrames
  long frameCount(double fps) const;
  // video time u falls on the title card
  bool inTitleCard(double u) const { return u < titleCard_; }
  // video time u falls on the closing answer card (after the run's last instant)
  bool inAnswerCard(double u) const { return answerCard_ > 0.0 && u >= length_ - answerCard_; }
  // the simulation time of video time u, in [0, duration]
  double simTime(double u) const;
  // how many times slower the video shows simulation time t (1 outside every window)
  double factorAt(double t) const;
  const std::vector<SlowWindow>& windows() const { return windows_; }

 private:
  double duration_, titleCard_, answerCard_, length_;
  std::vector<SlowWindow> windows_;  // merged
};

// the frames of each scene's video (2D or 3D) over `duration` (else its own) at `fps` (else its
// own), without slow motion, which needs the survey's impacts: throws UsageError past kMaxFrames
// before the survey runs the scene for hours
template <class Scene>
void boundFrames(const std::vector<Scene>& scenes, std::optional<double> duration, std::optional<double> fps) {
  for (const Scene& s : scenes)
    TimeMap(duration.value_or(s.model.duration), s.render.titleCard, {}, s.render.poll.answerCard)
        .frameCount(fps.value_or(s.render.fps));
}

// the scene's map: its title card, its answer card, and its slow_motion windows (around each of `impactTimes`, or
// explicit) over a run of `duration`
TimeMap timeMapFor(const render::scene::RenderDef& render, const std::vector<double>& impactTimes, double duration);

}  // namespace render::video

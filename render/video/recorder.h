// The recording loop (as MuJoCo's `record` sample): frame k shows the scene at exactly the simulation
// time that video time k / fps maps to (t = k / fps without a title card or slow motion), whatever
// the physics step, and is painted on this thread while a second thread hands the frames
// before it to the encoder and the PNG writer, so that drawing and encoding overlap.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/frame/frame_source.h"
#include "render/frame/scene_run.h"
#include "render/video/time_map.h"

namespace render::video {

// where finished frames go; called on the second thread, in frame order
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void frame(long index, const render::draw::Image& image) = 0;
};

// frames as numbered PNG files in a directory: frame-00000.png, frame-00001.png, …
class PngFrames : public FrameSink {
 public:
  // `count` sets the number of digits (at least 5)
  PngFrames(std::string directory, long count);
  void frame(long index, const render::draw::Image& image) override;
  // the printf pattern of the names, e.g. "frame-%05d.png" (what ffmpeg's image2 reader takes)
  const std::string& pattern() const { return pattern_; }

 private:
  std::string directory_, pattern_;
};

// frames 0 … map.frameCount(fps) − 1 into every sink: the title card while video time k / fps is on
// it (painted once), then the scene at map.simTime(k / fps), saying when it is slowed; `progress`
// (may be empty) is told after each frame is painted. Throws what a sink or the simulation throws,
// and Interrupted on Ctrl-C.
void record(render::frame::FrameSource& run, const TimeMap& map, double fps, const std::vector<FrameSink*>& sinks,
            const std::function<void(long done)>& progress = {});
// the same from a 2D scene's run
void record(render::frame::SceneRun& run, const TimeMap& map, double fps, const std::vector<FrameSink*>& sinks,
            const std::function<void(long done)>& progress = {});

}  // namespace render::video

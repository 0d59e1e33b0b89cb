// What the recording loop and the still pictures take frames from: a run of a scene, 2D
// (SceneRun) or 3D (render/frame3d), stepped forward to each time asked for.
#pragma once

#include <functional>

#include "render/draw/image.h"

namespace render::frame {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // the frame at exactly time t, not earlier than the last one asked for
  virtual render::draw::Image frameAt(double t) = 0;
  // the same into `frame`, whose storage a source may reuse (a video's few buffers); by default a copy
  virtual void frameAt(double t, render::draw::Image& frame) { frame = frameAt(t); }
  // the title card over the frame at t = 0 (title_card.h)
  virtual render::draw::Image titleCard() = 0;
  // the closing card with the poll's answer (`answer_card`)
  virtual render::draw::Image answerCard() = 0;
  // video frames say when they are slowed: how many times slower simulation time t is shown (empty: never)
  virtual void showSlowMotion(std::function<double(double t)> factorAt) = 0;
};

}  // namespace render::frame

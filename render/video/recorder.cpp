#include "render/video/recorder.h"

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "render/draw/png_io.h"
#include "render/jobs/interrupt.h"

namespace render::video {
using render::draw::Image;
using render::frame::FrameSource;
using render::frame::SceneRun;
using namespace render::jobs;
using namespace render::draw;
using namespace render::frame;
using namespace render::scene;

namespace {

// frames painted but not yet written: enough to absorb a slow frame on either side, while a
// 1280×720 frame is 3.7 MB
constexpr size_t kQueueFrames = 3;

// the frames between the painting thread and the writing thread, and back: a written frame's buffer
// is painted again, so that after the first few frames none is allocated (and its pages faulted in
// and zeroed by the kernel) or copied (a profile of a 720p render found a quarter of the main
// thread's time there)
class FrameQueue {
 public:
  // a buffer to paint into: a written frame's, or a new one while fewer than the queue holds exist
  Image take() {
    std::lock_guard lock(mutex_);
    if (free_.empty()) return {};
    Image image = std::move(free_.back());
    free_.pop_back();
    return image;
  }
  // false once the writer has failed: stop painting. With `shown`, the frame is that image (which
  // outlives the writing) and `image` a buffer passed along unpainted
  bool push(long index, Image image, const Image* shown = nullptr) {
    std::unique_lock lock(mutex_);
    roomLeft_.wait(lock, [&] { return queue_.size() < kQueueFrames || failure_; });
    if (failure_) return false;
    queue_.push_back({index, std::move(image), shown});
    ready_.notify_one();
    return true;
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_one();
  }
  // the writer's loop: until closed and empty, or a sink throws
  void drain(const std::vector<FrameSink*>& sinks) {
    for (;;) {
      Item item;
      {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [&] { return !queue_.empty() || closed_; });
        if (queue_.empty()) return;
        item = std::move(queue_.front());
        queue_.pop_front();
        roomLeft_.notify_one();
      }
      try {
        for (FrameSink* sink : sinks) sink->frame(item.index, item.shown ? *item.shown : item.image);
      } catch (...) {
        std::lock_guard lock(mutex_);
        failure_ = std::current_exception();
        roomLeft_.notify_one();
        return;
      }
      std::lock_guard lock(mutex_);
      free_.push_back(std::move(item.image));
    }
  }
  std::exception_ptr failure() {
    std::lock_guard lock(mutex_);
    return failure_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_, roomLeft_;
  struct Item {
    long index = 0;
    Image image;
    const Image* shown = nullptr;
  };
  std::deque<Item> queue_;
  std::vector<Image> free_;  // written frames, their buffers to be painted again
  bool closed_ = false;
  std::exception_ptr failure_;
};

}  // namespace

PngFrames::PngFrames(std::string directory, long count) : directory_(std::move(directory)) {
  int digits = 5;
  for (long n = 100000; n < count; n *= 10) ++digits;
  pattern_ = "frame-%0" + std::to_string(digits) + "ld.png";
}

void PngFrames::frame(long index, const Image& image) {
  char name[64];
  std::snprintf(name, sizeof name, pattern_.c_str(), index);
  writePng(image, directory_ + "/" + name);
}

namespace {

// a 2D scene's run as a source of frames
class SceneRunFrames final : public FrameSource {
 public:
  explicit SceneRunFrames(SceneRun& run) : run_(run) {}
  Image frameAt(double t) override { return run_.frameAt(t); }
  void frameAt(double t, Image& frame) override { run_.frameAt(t, frame); }
  Image titleCard() override { return run_.titleCard(); }
  Image answerCard() override { return run_.answerCard(); }
  void showSlowMotion(std::function<double(double)> factorAt) override { run_.showSlowMotion(std::move(factorAt)); }

 private:
  SceneRun& run_;
};

}  // namespace

void record(SceneRun& run, const TimeMap& map, double fps, const std::vector<FrameSink*>& sinks,
            const std::function<void(long)>& progress) {
  SceneRunFrames frames(run);
  record(frames, map, fps, sinks, progress);
}

void record(FrameSource& run, const TimeMap& map, double fps, const std::vector<FrameSink*>& sinks,
            const std::function<void(long)>& progress) {
  const long count = map.frameCount(fps);
  run.showSlowMotion([&map](double t) { return map.factorAt(t); });
  Image card, answer;
  FrameQueue queue;
  std::thread writer([&] { queue.drain(sinks); });
  std::exception_ptr failure;
  try {
    for (long k = 0; k < count; ++k) {
      checkInterrupted();
      // k / fps rather than a running sum: no drift, and the frame lands on the same instant as
      // a snapshot asked for at that time
      const double u = static_cast<double>(k) / fps;
      if (map.inTitleCard(u) && card.rgba.empty()) card = run.titleCard();
      const bool answered = !map.inTitleCard(u) && map.inAnswerCard(u);
      if (answered && answer.rgba.empty()) answer = run.answerCard();
      Image frame = queue.take();
      // a card's frames are the card itself, never copied (3.7 MB a 720p frame)
      const bool titled = map.inTitleCard(u);
      if (!titled && !answered) run.frameAt(map.simTime(u), frame);
      if (!queue.push(k, std::move(frame), titled ? &card : answered ? &answer : nullptr)) break;
      if (progress) progress(k + 1);
    }
  } catch (...) {
    failure = std::current_exception();
  }
  run.showSlowMotion({});
  queue.close();
  writer.join();
  if (failure) std::rethrow_exception(failure);
  if (std::exception_ptr f = queue.failure()) std::rethrow_exception(f);
}

}  // namespace render::video

// Video through the ffmpeg program: raw RGBA frames on its standard input, spawned with an argument
// vector (no shell, so no file name can inject a command), writing a temporary file beside the
// output that is renamed into place only when ffmpeg has finished well and the file reads back whole
// (container_check.h). A missing or failing ffmpeg is an error with the tail of what it printed.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "render/draw/image.h"

namespace render::video {

enum class VideoFormat { Mp4, Webm, Gif };

std::optional<VideoFormat> videoFormatFromName(std::string_view name);
// the file extension, without the dot: "mp4", "webm", "gif"
const char* videoExtension(VideoFormat format);

// ffmpeg's arguments (after the program name) to read width × height RGBA frames at `fps` from its
// standard input and encode them into `path`
std::vector<std::string> ffmpegArguments(VideoFormat format, int width, int height, double fps, const std::string& path);

class VideoWriter {
 public:
  // starts ffmpeg; throws std::runtime_error when it cannot be started (not installed)
  VideoWriter(const std::string& path, VideoFormat format, int width, int height, double fps,
              const std::string& program = "ffmpeg");
  // an unfinished video is abandoned: ffmpeg stopped, the temporary file removed
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // one frame of the size given; throws std::runtime_error with ffmpeg's message when it has failed
  void write(const render::draw::Image& frame);
  // close ffmpeg's input, wait for it, check the file and rename the video into place; throws
  // std::runtime_error (the previous video at the path is then left as it was)
  void finish();
  const std::string& temporaryPath() const { return temporary_; }

 private:
  // stop feeding ffmpeg, wait for it, remove the temporary file and throw `what` with its message
  [[noreturn]] void fail(const std::string& what);
  // ffmpeg's exit status, once it has exited (and its standard error read to the end); an
  // interruptible wait throws Interrupted on Ctrl-C (the destructor then stops ffmpeg)
  int wait(bool interruptible = true);
  // " (ffmpeg exited with status N); ffmpeg said:\n<the tail of its standard error>"
  std::string diagnosis(int status) const;

  std::string path_, temporary_, program_;
  VideoFormat format_;
  int width_, height_;
  long frames_ = 0;  // frames written
  pid_t pid_ = -1;
  int input_ = -1;           // ffmpeg's standard input
  int errors_ = -1;          // ffmpeg's standard error
  std::thread errorReader_;  // keeps the tail of ffmpeg's standard error
  std::string errorTail_;
};

}  // namespace render::video

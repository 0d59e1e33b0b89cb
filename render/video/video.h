// Video through the ffmpeg program: raw RGBA frames on its standard input, spawned with an argument
// vector (no shell, so no file name can inject a command), writing a temporary file beside the
// output that is renamed into place only when ffmpeg has finished well. A missing or failing ffmpeg
// is an error with the tail of what it printed.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "render/draw/image.h"

namespace render::video {
using namespace render::draw;

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
  void write(const Image& frame);
  // close ffmpeg's input, wait for it and rename the video into place; throws std::runtime_error
  void finish();
  const std::string& temporaryPath() const { return temporary_; }

 private:
  // stop feeding ffmpeg, wait for it, remove the temporary file and throw `what` with its message
  [[noreturn]] void fail(const std::string& what);
  // ffmpeg's exit status, once it has exited (and its standard error read to the end)
  int wait();
  // " (ffmpeg exited with status N); ffmpeg said:\n<the tail of its standard error>"
  std::string diagnosis(int status) const;

  std::string path_, temporary_, program_;
  int width_, height_;
  pid_t pid_ = -1;
  int input_ = -1;           // ffmpeg's standard input
  int errors_ = -1;          // ffmpeg's standard error
  std::thread errorReader_;  // keeps the tail of ffmpeg's standard error
  std::string errorTail_;
};

}  // namespace render::video

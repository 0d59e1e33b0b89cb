#include "render/video/video.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "render/jobs/interrupt.h"
#include "render/jobs/process.h"
#include "render/jobs/stale_parts.h"
#include "render/video/container_check.h"

namespace render::video {
using render::draw::Image;
using namespace render::jobs;
using namespace render::draw;

namespace {

// the last lines of ffmpeg's standard error that a message quotes
constexpr size_t kTailChars = 2000;
// how often a wait for ffmpeg looks at the interrupt flag, µs, and for how many ticks an ffmpeg told
// to stop may take before it is killed (2 s)
constexpr int kTickMicroseconds = 20000;
constexpr int kGraceTicks = 100;

std::string fpsText(double fps) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", fps);
  return buf;
}

// out/a/b.mp4 → out/a/.b.part-<pid>.mp4: the same directory (so the rename is atomic), hidden,
// and still ending in the format's extension
std::string temporaryName(const std::string& path) {
  const std::filesystem::path p(path);
  std::ostringstream name;
  name << '.' << p.stem().string() << ".part-" << ::getpid() << p.extension().string();
  return (p.parent_path() / name.str()).string();
}

}  // namespace

std::optional<VideoFormat> videoFormatFromName(std::string_view name) {
  if (name == "mp4") return VideoFormat::Mp4;
  if (name == "webm") return VideoFormat::Webm;
  if (name == "gif") return VideoFormat::Gif;
  return std::nullopt;
}

const char* videoExtension(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4: return "mp4";
    case VideoFormat::Webm: return "webm";
    case VideoFormat::Gif: return "gif";
  }
  return "mp4";
}

std::vector<std::string> ffmpegArguments(VideoFormat format, int width, int height, double fps, const std::string& path) {
  std::vector<std::string> a = {"-hide_banner", "-loglevel", "error", "-y",
                                // the input: raw frames on standard input, top row first
                                "-f", "rawvideo", "-pix_fmt", "rgba", "-video_size",
                                std::to_string(width) + "x" + std::to_string(height), "-framerate", fpsText(fps), "-i", "pipe:0",
                                "-an"};
  const std::vector<std::string> codec = [&]() -> std::vector<std::string> {
    switch (format) {
      case VideoFormat::Mp4:
        // H.264 in yuv420p plays in every browser; the index up front (+faststart) lets it start
        // before it has loaded; CRF 18 keeps thin lines and text sharp
        return {"-c:v",      "libx264",  "-preset", "fast",      "-crf",       "18", "-tune",
                "animation", "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4"};
      case VideoFormat::Webm:
        // VP9 at constant quality (-b:v 0 with -crf), multithreaded by rows
        return {"-c:v",      "libvpx-vp9", "-b:v",      "0", "-crf",     "32",      "-row-mt", "1",
                "-deadline", "good",       "-cpu-used", "4", "-pix_fmt", "yuv420p", "-f",      "webm"};
      case VideoFormat::Gif:
        // one palette made for the whole clip, then used for every frame
        return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", "-loop", "0", "-f", "gif"};
    }
    return {};
  }();
  a.insert(a.end(), codec.begin(), codec.end());
  a.push_back(path);
  return a;
}

VideoWriter::VideoWriter(const std::string& path, VideoFormat format, int width, int height, double fps,
                         const std::string& program)
    : path_(path), temporary_(temporaryName(path)), program_(program), format_(format), width_(width), height_(height) {
  // a write to an ffmpeg that has died is an error to report (EPIPE), not a signal that kills us
  ::signal(SIGPIPE, SIG_IGN);
  removeStaleParts(path_);
  // "file:" and an absolute path: ffmpeg reads "run:1/…" as a protocol and "-weird/…" as an option
  std::vector<std::string> args =
      ffmpegArguments(format, width, height, fps, "file:" + std::filesystem::absolute(temporary_).string());
  args.insert(args.begin(), program_);
  Child child;
  try {
    child = spawnChild(args, Stream::Pipe, Stream::Null, Stream::Pipe);
  } catch (const SpawnError& e) {
    throw std::runtime_error(std::string(e.what()) +
                             (e.missing() ? "; install it, e.g. apt-get install ffmpeg" : "; free some and run again"));
  }
  pid_ = child.pid;
  input_ = child.input;
  errors_ = child.errors;
  widenPipe(input_, static_cast<size_t>(width) * height * 4);
  errorReader_ = std::thread([this] { readTail(errors_, errorTail_, kTailChars); });
  // writes that never block, so that Ctrl-C is seen while ffmpeg is stalled and reads nothing
  ::fcntl(input_, F_SETFL, ::fcntl(input_, F_GETFL) | O_NONBLOCK);
}

VideoWriter::~VideoWriter() {
  if (pid_ <= 0) return;
  if (input_ >= 0) ::close(input_);
  ::kill(pid_, SIGTERM);
  // an ffmpeg stopped or stuck in the kernel may not end on SIGTERM: SIGKILL after a grace period
  for (int k = 0; k < kGraceTicks; ++k) {
    if (::waitpid(pid_, nullptr, WNOHANG) == pid_) pid_ = -1;
    if (pid_ < 0) break;
    ::usleep(kTickMicroseconds);
  }
  if (pid_ > 0) ::kill(pid_, SIGKILL);
  wait(false);
  std::remove(temporary_.c_str());
}

int VideoWriter::wait(bool interruptible) {
  int status = 0;
  // ffmpeg writing its trailer to a stalled disk must not make Ctrl-C wait for it
  while (interruptible && pid_ > 0) {
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_ || (done < 0 && errno != EINTR)) {
      pid_ = -1;
      break;
    }
    checkInterrupted();
    ::usleep(kTickMicroseconds);
  }
  if (pid_ > 0) status = waitChild(pid_);
  pid_ = -1;
  if (errorReader_.joinable()) errorReader_.join();
  if (errors_ >= 0) ::close(errors_);
  errors_ = -1;
  return status;
}

std::string VideoWriter::diagnosis(int status) const {
  std::ostringstream m;
  if (WIFEXITED(status)) m << " (ffmpeg exited with status " << WEXITSTATUS(status) << ")";
  else if (WIFSIGNALED(status)) m << " (ffmpeg was killed by signal " << WTERMSIG(status) << ")";
  std::string tail = errorTail_.size() > kTailChars ? errorTail_.substr(errorTail_.size() - kTailChars) : errorTail_;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
  if (!tail.empty()) m << "; ffmpeg said:\n" << tail;
  return m.str();
}

void VideoWriter::fail(const std::string& what) {
  if (input_ >= 0) ::close(input_);
  input_ = -1;
  const int status = wait();
  std::remove(temporary_.c_str());
  checkChildInterrupted(status);
  throw std::runtime_error(what + diagnosis(status));
}

void VideoWriter::write(const Image& frame) {
  if (frame.width != width_ || frame.height != height_) throw std::logic_error("a video frame of the wrong size");
  const uint8_t* data = frame.rgba.data();
  size_t left = frame.rgba.size();
  while (left > 0) {
    const ssize_t n = ::write(input_, data, left);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) {
      checkInterrupted();
      pollfd ready{input_, POLLOUT, 0};
      ::poll(&ready, 1, kTickMicroseconds / 1000);
      continue;
    }
    if (n < 0) fail(path_ + ": ffmpeg stopped reading frames");
    data += n;
    left -= static_cast<size_t>(n);
  }
  ++frames_;
}

void VideoWriter::finish() {
  ::close(input_);
  input_ = -1;
  const int status = wait();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::remove(temporary_.c_str());
    checkChildInterrupted(status);
    throw std::runtime_error(path_ + ": ffmpeg could not encode the video" + diagnosis(status));
  }
  // ffmpeg 5.1 exits 0 after "Error writing trailer of …: No space left on device": at -loglevel
  // error anything it says is an error, and the file must read back whole
  std::string defect = errorTail_.empty() ? videoDefect(temporary_, format_, frames_) : "ffmpeg reported an error";
  if (!defect.empty()) {
    std::remove(temporary_.c_str());
    throw std::runtime_error(path_ + ": the video is incomplete (" + defect +
                             "), so the previous file is kept; is the disk full?" + diagnosis(status));
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temporary_.c_str());
    throw std::runtime_error(path_ + ": could not finish writing (" + why + ")");
  }
}

}  // namespace render::video

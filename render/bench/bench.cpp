// rigidreel_bench (`make bench`): timings, never asserted in tests. The frames per second of a 720p
// render to mp4 with and without PNG frames, against ffmpeg's own time to encode the same frames
// (the stacks, against Box2D 2.4, are rigidreel_stack_bench's). Results go to out/bench/render.csv
// and a summary on stdout; ratios are measured in one run, since these machines are noisy.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"
#include "render/video/video.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Timed {
  double seconds;
  int status;
};

Timed timeProgram(const std::vector<std::string>& argv) {
  const auto start = Clock::now();
  const render::jobs::ProcessResult r = render::jobs::runProgram(argv, "");
  if (r.status != 0) std::cerr << argv[0] << " failed (" << r.status << "): " << r.errorTail << '\n';
  return {secondsSince(start), r.status};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string rigidreel = argc > 1 ? argv[1] : "build/rigidreel";
  const std::string scene = argc > 2 ? argv[2] : "scenes/three_collisions_poll.yaml";
  fs::create_directories("out/bench");

  // the renderer: a 720p video of `scene`, with and without PNG frames, against ffmpeg alone
  const double fps = 60.0, duration = 2.0;
  const int frames = static_cast<int>(fps * duration);
  const std::vector<std::string> render{rigidreel, "render", scene, "-o", "out/bench/render", "--size", "1280x720",
                                        "--fps", "60", "--duration", "2", "--quiet"};
  const Timed video = timeProgram(render);
  std::vector<std::string> withFrames = render;
  withFrames.push_back("--frames");
  const Timed both = timeProgram(withFrames);
  // the same frames as raw RGBA (decoded from the video), then encoded by ffmpeg alone with the
  // arguments rigidreel gives it
  const std::string stem = fs::path(scene).stem().string();
  const std::string mp4 = "out/bench/render/" + stem + "/" + stem + ".mp4";
  const std::string raw = "out/bench/frames.rgba";
  timeProgram({"ffmpeg", "-v", "error", "-y", "-i", mp4, "-f", "rawvideo", "-pix_fmt", "rgba", raw});
  std::vector<std::string> encode{"ffmpeg"};
  for (const std::string& a : render::video::ffmpegArguments(render::video::VideoFormat::Mp4, 1280, 720, fps, "out/bench/ffmpeg-only.mp4"))
    encode.push_back(a == "pipe:0" ? raw : a);
  const Timed ffmpeg = timeProgram(encode);
  fs::remove(raw);

  std::ofstream out("out/bench/render.csv");
  out << "what,frames,seconds,frames_per_second\n";
  auto row = [&](const char* what, double seconds) {
    out << what << ',' << frames << ',' << render::jobs::formatNumber(seconds) << ',' << render::jobs::formatNumber(frames / seconds) << '\n';
    std::printf("%-34s %6.2f s, %7.1f frames per second\n", what, seconds, frames / seconds);
  };
  row("720p render to mp4", video.seconds);
  row("720p render to mp4 and PNG frames", both.seconds);
  row("ffmpeg alone, same raw frames", ffmpeg.seconds);
  out << "ratio_render_to_ffmpeg,," << render::jobs::formatNumber(video.seconds / ffmpeg.seconds) << ",\n";
  std::printf("whole render / ffmpeg's own encoding time: %.2f\nwrote out/bench/render.csv\n",
              video.seconds / ffmpeg.seconds);
  return video.status == 0 && both.status == 0 && ffmpeg.status == 0 ? 0 : 1;
}

// rigidreel_bench (`make bench`): timings, never asserted in tests. Simulation milliseconds per
// step on Box2D's pyramid benchmark (bases 20 and 100), and the frames per second of a 720p
// render to mp4 with and without PNG frames, against ffmpeg's own time to encode the same frames.
// Results go to out/bench/*.csv and a summary on stdout; ratios are measured in one run, since
// these machines are noisy.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"
#include "render/video/video.h"
#include "sim/scene/scene_build.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Box2D's Pyramid test: 1 m boxes from (-7, 0.75) stepping (0.5625, 1.25) per row and 1.125 along
// a row, on a ground box; gravity 10, dt 1/60, friction 0.6, 8 velocity and 3 position iterations
sim::scene::SceneDef pyramid(int base) {
  sim::scene::SceneDef def;
  def.name = "pyramid";
  def.name.append(std::to_string(base));
  def.gravity = {0, -10};
  def.dt = 1.0 / 60.0;
  def.friction = 0.6;
  def.restitution = 0.0;
  def.collisions = sim::world::CollisionMethod::Sequential;
  def.velocityIterations = 8;
  def.positionIterations = 3;
  sim::scene::BodyDef ground;
  ground.name = "ground";
  ground.shape = sim::core::makeBox(2.0 * base + 40.0, 1.0);
  ground.position = {0, -0.5};
  ground.isStatic = true;
  def.bodies.push_back(ground);
  for (int row = 0; row < base; ++row)
    for (int j = 0; j < base - row; ++j) {
      sim::scene::BodyDef b;
      b.name = "b";
      b.name.append(std::to_string(row)).append("_").append(std::to_string(j));
      b.shape = sim::core::makeBox(1.0, 1.0);
      b.position = {-7.0 + 0.5625 * row + 1.125 * j, 0.75 + 1.25 * row};
      def.bodies.push_back(b);
    }
  return def;
}

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

  // the simulation: ms per step, timed after building, over a fixed number of steps
  std::ofstream sim("out/bench/simulation.csv");
  sim << "scene,bodies,steps,ms_per_step\n";
  for (const auto& [base, steps] : {std::pair{20, 600}, std::pair{100, 120}}) {
    const sim::scene::SceneDef def = pyramid(base);
    sim::world::World world = sim::scene::buildWorld(def);
    world.start();
    const auto start = Clock::now();
    world.advanceTo(steps * def.dt);
    const double ms = 1000.0 * secondsSince(start) / steps;
    sim << def.name << ',' << def.bodies.size() - 1 << ',' << steps << ',' << render::jobs::formatNumber(ms) << '\n';
    std::printf("pyramid base %3d (%4zu boxes): %8.3f ms per step over %d steps\n", base, def.bodies.size() - 1, ms, steps);
  }

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
  std::printf("whole render / ffmpeg's own encoding time: %.2f\nwrote out/bench/simulation.csv and out/bench/render.csv\n",
              video.seconds / ffmpeg.seconds);
  return video.status == 0 && both.status == 0 && ffmpeg.status == 0 ? 0 : 1;
}

// rigidreel_bench (`make bench`): timings, never asserted in tests (the stacks, against Box2D 2.4,
// are rigidreel_stack_bench's). The start-up of `check` on one scene; the
// video pipeline's parts per frame at 720p and 1080p (drawing, read-back, handing over, encoding)
// and the whole render against ffmpeg alone encoding the same frames; the lecture pack's wall time.
// Given a second rigidreel (a baseline build), the start-up, renders and lecture pack are timed for
// it too, in the same run. Results go to out/bench/*.csv and a summary on stdout; ratios are
// measured in one run, since these machines are noisy.
//
// usage: rigidreel_bench RIGIDREEL SCENE [BASELINE_RIGIDREEL]
#include <sys/resource.h>
#include <unistd.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "render/draw/gl_canvas.h"
#include "render/frame/scene_run.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"
#include "render/scene/scene_style.h"
#include "render/video/render_plan.h"
#include "render/video/video.h"
#include "sim/yaml/scene_source.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Timed {
  double seconds;  // wall
  double cpu;      // user and system, of the program and the children it waited for (ffmpeg, jobs)
  int status;
};

// the CPU seconds of every child waited for so far
double childrenCpu() {
  rusage u{};
  ::getrusage(RUSAGE_CHILDREN, &u);
  auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

// (`failureExpected`: the render into the stand-in, whose empty video rigidreel's container check
// rejects after every frame was handed over)
Timed timeProgram(const std::vector<std::string>& argv, bool failureExpected = false) {
  const double cpu = childrenCpu();
  const auto start = Clock::now();
  const render::jobs::ProcessResult r = render::jobs::runProgram(argv, "");
  if (r.status != 0 && !failureExpected) std::cerr << argv[0] << " failed (" << r.status << "): " << r.errorTail << '\n';
  return {secondsSince(start), childrenCpu() - cpu, r.status};
}

// the median of `runs` timings of argv, in seconds
double medianTime(const std::vector<std::string>& argv, int runs) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) t.push_back(timeProgram(argv).seconds);
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// rigidreel's own work per frame, in this process, in ms: a frame drawn (the simulation stepped to
// its instant, the GL drawing at each sample position, the samples resolved, the text; the
// read-back excluded), read back (the frame copied out of GL, measured on frames of the background
// alone) and handed over (written into a pipe to a reader that discards it)
struct FrameParts {
  double drawing = 0.0, readback = 0.0, handover = 0.0;
};

// the parts, drawing the frames of `out` as the recorder does, and keeping them in `raw` (RGBA)
FrameParts measureParts(const render::video::PlannedVariant& v, const render::video::VideoOutput& out,
                        const std::string& raw) {
  using namespace render::draw;
  FrameParts parts;
  GlContext gl(out.width, out.height);
  TextRenderer text;
  Image frame, card;
  std::ofstream file(raw, std::ios::binary);
  {
    render::frame::SceneRun run(v.scene, out.camera, v.survey, &gl, &text);
    for (long k = 0; k < out.frameCount; ++k) {
      const double u = static_cast<double>(k) / out.fps;
      const auto start = Clock::now();
      if (out.timeMap.inTitleCard(u)) {
        if (card.rgba.empty()) card = run.titleCard();
        frame = card;
      } else {
        run.frameAt(out.timeMap.simTime(u), frame);
      }
      parts.drawing += secondsSince(start);
      file.write(reinterpret_cast<const char*>(frame.rgba.data()), static_cast<std::streamsize>(frame.rgba.size()));
    }
  }
  // the read-back alone: a frame of the background only (drawn once, not at each sample position:
  // GlContext::drawnWithin), GL finished, then read
  const Style style = render::scene::makeStyle(v.scene, out.height);
  GlCanvas canvas(gl, text, style);
  for (long k = 0; k < out.frameCount; ++k) {
    canvas.begin(out.camera);
    glFinish();
    const auto start = Clock::now();
    canvas.finish(frame);
    parts.readback += secondsSince(start);
  }
  // the frame-drawing time included a read-back each
  parts.drawing -= parts.readback;
  // handing over: the frames into a pipe as wide as the video writer's, to `cat` into /dev/null
  render::jobs::Child cat = render::jobs::spawnChild({"cat"}, render::jobs::Stream::Pipe, render::jobs::Stream::Null,
                                                     render::jobs::Stream::Null);
  render::jobs::widenPipe(cat.input, frame.rgba.size());
  const auto start = Clock::now();
  for (long k = 0; k < out.frameCount; ++k)
    for (size_t done = 0; done < frame.rgba.size();) {
      const ssize_t n = ::write(cat.input, frame.rgba.data() + done, frame.rgba.size() - done);
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
  ::close(cat.input);
  render::jobs::waitChild(cat.pid);
  parts.handover = secondsSince(start);
  const double ms = 1000.0 / static_cast<double>(out.frameCount);
  return {parts.drawing * ms, parts.readback * ms, parts.handover * ms};
}

// a stand-in for ffmpeg on PATH: reads the frames and discards them, leaves an empty output
std::string writeStandIn(const std::string& dir) {
  fs::create_directories(dir);
  const std::string path = dir + "/ffmpeg";
  std::ofstream(path) << "#!/bin/sh\n# rigidreel_bench's ffmpeg: the frames read and discarded\nfor last; do :; done\n"
                         "cat > /dev/null && : > \"$last\"\n";
  fs::permissions(path, fs::perms::owner_all);
  return dir;
}

// argv run with `dir` (the stand-in ffmpeg) first on PATH
Timed timeWithPath(const std::vector<std::string>& argv, const std::string& dir) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (fs::absolute(dir).string() + ":" + saved).c_str(), 1);
  const Timed t = timeProgram(argv, true);
  ::setenv("PATH", saved.c_str(), 1);
  return t;
}

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string rigidreel = argc > 1 ? argv[1] : "build/rigidreel";
  const std::string scene = argc > 2 ? argv[2] : "scenes/three_collisions_poll.yaml";
  const std::string baseline = argc > 3 ? argv[3] : "";
  fs::create_directories("out/bench");
  // each line as it comes: the lecture packs take minutes
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  // every timing of the pipeline, a row each: what, the program timed, the frame size, seconds, ms per frame
  std::ofstream csv("out/bench/pipeline.csv");
  csv << "what,program,size,frames,seconds,ms_per_frame,cpu_seconds\n";
  auto row = [&](const std::string& what, const std::string& program, const std::string& size, long frames, double seconds,
                 double cpu = -1.0) {
    csv << what << ',' << program << ',' << size << ',' << frames << ',' << render::jobs::formatNumber(seconds) << ','
        << (frames > 0 ? render::jobs::formatNumber(1000.0 * seconds / frames) : "") << ','
        << (cpu >= 0.0 ? render::jobs::formatNumber(cpu) : "") << '\n';
  };
  std::vector<std::pair<std::string, std::string>> programs = {{"rigidreel", rigidreel}};
  if (!baseline.empty()) programs.push_back({"baseline", baseline});

  // start-up: `check` of one scene, the median of 21 runs
  const std::string checked = "scenes/poll_bar_impulse.yaml";
  for (const auto& [name, program] : programs) {
    const double s = medianTime({program, "check", checked}, 21);
    row("check start-up", name, "", 0, s);
    std::printf("%-9s check %s: %6.1f ms (median of 21)\n", name.c_str(), checked.c_str(), 1000.0 * s);
  }

  // the video pipeline at 720p and 1080p, 2 s at 60 fps of `scene`
  const double fps = 60.0, duration = 2.0;
  const std::string standIn = writeStandIn("out/bench/stand-in");
  const std::string stem = fs::path(scene).stem().string();
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    render::video::VideoRequest request;
    request.root = "out/bench/render";
    request.size = render::video::FrameSize{w, h};
    request.fps = fps;
    request.duration = duration;
    const render::video::RenderPlan plan = render::video::planVideos(
        [&](const std::string& variant) { return render::scene::readScene(sim::yaml::readSceneSource(scene, variant)); },
        request);
    const render::video::VideoOutput& out = plan.videos.front();
    const long frames = out.frameCount;
    const std::string raw = "out/bench/frames-" + size + ".rgba";
    const FrameParts parts = measureParts(plan.variants[out.variant], out, raw);

    const std::vector<std::string> render{"", "render", scene, "-o", "out/bench/render", "--size", size, "--fps", "60",
                                          "--duration", "2", "--quiet"};
    auto renderWith = [&](const std::string& program) {
      std::vector<std::string> a = render;
      a[0] = program;
      return a;
    };
    // rigidreel's side alone: its frames into the stand-in that discards them
    const Timed side = timeWithPath(renderWith(rigidreel), standIn);
    // ffmpeg alone, with the arguments rigidreel gives it, on the same frames read from a file
    std::vector<std::string> encode{"ffmpeg"};
    for (const std::string& a : render::video::ffmpegArguments(render::video::VideoFormat::Mp4, w, h, fps, "out/bench/ffmpeg-only.mp4"))
      encode.push_back(a == "pipe:0" ? raw : a);
    const Timed ffmpeg = timeProgram(encode);
    std::vector<std::pair<std::string, Timed>> wholes;
    for (const auto& [name, program] : programs) wholes.push_back({name, timeProgram(renderWith(program))});
    // the same frames make the same video: the frames measured here are the ones rendered
    const std::string mp4 = "out/bench/render/" + stem + "/" + stem + ".mp4";
    const bool same = fileText(mp4) == fileText("out/bench/ffmpeg-only.mp4");
    fs::remove(raw);

    row("drawing", "rigidreel", size, frames, parts.drawing * frames / 1000.0);
    row("readback", "rigidreel", size, frames, parts.readback * frames / 1000.0);
    row("handover", "rigidreel", size, frames, parts.handover * frames / 1000.0);
    row("render into a discarding reader", "rigidreel", size, frames, side.seconds, side.cpu);
    row("encoding (ffmpeg alone)", "ffmpeg", size, frames, ffmpeg.seconds, ffmpeg.cpu);
    const double perFrame = 1000.0 / frames;
    std::printf("\n%s, %ld frames of %s, ms per frame:\n", size.c_str(), frames, stem.c_str());
    std::printf("  drawing %6.2f | read-back %5.2f | handing over %5.2f | encoding (ffmpeg alone) %6.2f\n", parts.drawing,
                parts.readback, parts.handover, ffmpeg.seconds * perFrame);
    std::printf("  rigidreel's side into a discarding reader: %6.2f (CPU %.2f)\n", side.seconds * perFrame, side.cpu * perFrame);
    for (const auto& [name, whole] : wholes) {
      row("whole render", name, size, frames, whole.seconds, whole.cpu);
      std::printf("  %-9s whole render %6.2f, %.2f x ffmpeg alone (CPU time: %.2f x)\n", name.c_str(),
                  whole.seconds * perFrame, whole.seconds / ffmpeg.seconds, whole.cpu / ffmpeg.cpu);
      csv << "ratio whole render to ffmpeg alone," << name << ',' << size << ",,"
          << render::jobs::formatNumber(whole.seconds / ffmpeg.seconds) << ",\n";
    }
    std::printf("  rigidreel's video is ffmpeg alone's, byte for byte: %s\n", same ? "yes" : "NO");
  }

  // the lecture pack (scenes/lecture, as `make lecture` makes it)
  std::printf("\n");
  for (const auto& [name, program] : programs) {
    const std::string dir = "out/bench/lecture-" + name;
    fs::remove_all(dir);
    const Timed t = timeProgram({program, "lecture", "scenes/lecture", "-o", dir, "--quiet"});
    row("lecture pack", name, "", 0, t.seconds, t.cpu);
    std::printf("%-9s lecture pack: %6.1f s (CPU time %6.1f s)\n", name.c_str(), t.seconds, t.cpu);
  }
  std::printf("wrote out/bench/pipeline.csv\n");
  return 0;
}

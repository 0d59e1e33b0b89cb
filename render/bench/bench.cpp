// rigidreel_bench (`make bench`): timings, never asserted in tests (the stacks, against Box2D 2.4,
// are rigidreel_stack_bench's). The start-up of `check` on one scene; the
// video pipeline's parts per frame at 720p and 1080p (drawing, read-back, handing over, encoding)
// and the whole render against ffmpeg alone encoding the same frames; the lecture pack's wall time.
// Given a second rigidreel (a baseline build), the start-up, renders and lecture pack are timed for
// it too, in the same run. A table goes to stdout, and with `--csv FILE` a row per measure to FILE
// (`make bench` writes render/bench/results/renders.csv; its columns: render/bench/README.md),
// after comment lines naming the command, machine, date and commit, written whole when the run
// ends. Ratios are measured in one run, since these machines are noisy.
//
// usage: rigidreel_bench RIGIDREEL SCENE [BASELINE_RIGIDREEL] [--csv FILE] [--renders-only | --antialiasing]
// (--renders-only: the 720p renders alone, the poll and the pyramids on a box ground and on a half-plane;
// no start-up, 1080p or lecture pack;
// --antialiasing: the poll's and the pyramids' 720p frames at 1, 2 and 4 samples a pixel, their cost
// split and their difference from the 4-sample frames, with frames to look at in out/bench/antialiasing;
// no CSV)
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "bench_csv.h"
#include "render/draw/gl_canvas.h"
#include "render/draw/png_io.h"
#include "render/frame/frame_painter.h"
#include "render/frame/history.h"
#include "render/frame/kept_run.h"
#include "render/frame/scene_run.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"
#include "render/scene/scene_style.h"
#include "render/video/render_plan.h"
#include "render/video/video.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_source.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

// the rounds of each render measure, taken in turn, whose median is reported
constexpr int kRounds = 3;

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

// the median of timings, wall and processor time each (a timing's status is the last one's)
Timed median(std::vector<Timed> timings) {
  Timed m = timings.back();
  std::sort(timings.begin(), timings.end(), [](const Timed& a, const Timed& b) { return a.seconds < b.seconds; });
  m.seconds = timings[timings.size() / 2].seconds;
  std::sort(timings.begin(), timings.end(), [](const Timed& a, const Timed& b) { return a.cpu < b.cpu; });
  m.cpu = timings[timings.size() / 2].cpu;
  return m;
}

// the median of `runs` timings of argv, in seconds
double medianTime(const std::vector<std::string>& argv, int runs) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) t.push_back(timeProgram(argv).seconds);
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// rigidreel's own work per frame, in this process, in ms: a frame drawn (the simulation taken to
// its instant, the GL drawing at each sample position, the samples resolved, the text; the
// read-back excluded), read back (the frame copied out of GL, measured on frames of the background
// alone) and handed over (written into a pipe to a reader that discards it)
struct FrameParts {
  double drawing = 0.0, readback = 0.0, handover = 0.0;
  double simulation = 0.0;  // of the drawing's time, the world taken to the frames' instants
};

// the drawing's run alone taken to each frame's instant as SceneRun takes it (from the survey's kept
// states where it kept them, stepping the rest), with the history the frames record: the
// simulation's share of a frame, s in all
double simulationSeconds(const render::video::PlannedVariant& v, const render::video::VideoOutput& out) {
  const render::frame::FramePainter painter(v.scene, out.camera, v.survey);
  sim::world::World world = sim::scene::buildWorld(v.scene.model);
  render::frame::History history(world, painter.historyOptions());
  render::frame::PlanarRun run({std::move(world), std::move(history)}, v.scene.model.duration);
  render::frame::goOnFrom(run, v.survey.kept, painter.historyOptions());
  const auto start = Clock::now();
  for (long k = 0; k < out.frameCount; ++k) {
    const double u = static_cast<double>(k) / out.fps;
    if (!out.timeMap.inTitleCard(u)) run.reach(out.timeMap.simTime(u));
  }
  return secondsSince(start);
}

// the parts, drawing the frames of `out` as the recorder does, and keeping them in `raw` (RGBA)
FrameParts measureParts(const render::video::PlannedVariant& v, const render::video::VideoOutput& out, const std::string& raw) {
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
  // the frame-drawing time included a read-back each, and the simulation
  parts.drawing -= parts.readback;
  parts.simulation = simulationSeconds(v, out);
  parts.drawing -= parts.simulation;
  // handing over: the frames into a pipe as wide as the video writer's, to `cat` into /dev/null
  render::jobs::Child cat =
      render::jobs::spawnChild({"cat"}, render::jobs::Stream::Pipe, render::jobs::Stream::Null, render::jobs::Stream::Null);
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
  return {parts.drawing * ms, parts.readback * ms, parts.handover * ms, parts.simulation * ms};
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

// the process's CPU seconds, llvmpipe's threads included
double processCpu() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Anti-aliasing's cost and look: the frames of `out` drawn at 1, 2 and 4 samples a pixel side by side
// (one run each, frame by frame), each one's time split as GlContext measures it, and each frame
// compared with the 4-sample one: the largest and mean difference of a channel (0-255) and the share
// of pixels that differ at all. Frame `shown` of each is written to out/bench/antialiasing.
void compareAntialiasing(const render::video::PlannedVariant& v, const render::video::VideoOutput& out, const std::string& stem) {
  using namespace render::draw;
  // every frame at 4, 2 and 1 samples, then the default (4, or 2 where GlCanvas finds the frame dense)
  const Antialiasing kinds[] = {{1, 4, false}, {1, 2, false}, {1, 1, false}, defaultAntialiasing()};
  const char* names[] = {"4 samples", "2 samples", "1 sample ", "default  "};
  const char* files[] = {"s4", "s2", "s1", "default"};
  struct Drawing {
    std::unique_ptr<GlContext> gl;
    std::unique_ptr<render::frame::SceneRun> run;
    ReadCost cost;
    double wall = 0.0, cpu = 0.0;
    int maxDiff = 0;
    double sumDiff = 0.0, differing = 0.0;
    Image frame;
  };
  TextRenderer text;
  std::vector<Drawing> d(4);
  for (size_t i = 0; i < d.size(); ++i) {
    d[i].gl = std::make_unique<GlContext>(out.width, out.height, kinds[i]);
    d[i].gl->measureInto(&d[i].cost);
    d[i].run = std::make_unique<render::frame::SceneRun>(v.scene, out.camera, v.survey, d[i].gl.get(), &text);
  }
  const std::string dir = "out/bench/antialiasing";
  fs::create_directories(dir);
  const long shown = out.frameCount - 1;
  long frames = 0;
  for (long k = 0; k < out.frameCount; ++k) {
    const double u = static_cast<double>(k) / out.fps;
    if (out.timeMap.inTitleCard(u)) continue;
    ++frames;
    for (Drawing& x : d) {
      x.gl->makeCurrent();
      const double cpu = processCpu();
      const auto start = Clock::now();
      x.run->frameAt(out.timeMap.simTime(u), x.frame);
      x.wall += secondsSince(start);
      x.cpu += processCpu() - cpu;
    }
    const std::vector<uint8_t>& ref = d[0].frame.rgba;
    for (Drawing& x : d) {
      long diff = 0;
      for (size_t p = 0; p < ref.size(); p += 4) {
        bool any = false;
        for (size_t c = 0; c < 3; ++c) {
          const int e = std::abs(static_cast<int>(x.frame.rgba[p + c]) - static_cast<int>(ref[p + c]));
          x.maxDiff = std::max(x.maxDiff, e);
          x.sumDiff += e;
          any |= e > 0;
        }
        diff += any;
      }
      x.differing += static_cast<double>(diff) / static_cast<double>(ref.size() / 4);
    }
    if (k == shown)
      for (size_t i = 0; i < d.size(); ++i) writePng(d[i].frame, dir + "/" + stem + "-" + files[i] + ".png");
  }
  const double ms = 1000.0 / static_cast<double>(frames);
  const double channels = static_cast<double>(frames) * out.width * out.height * 3;
  std::printf("\n%s, %ld frames at %dx%d, ms per frame (wall; the rest is the simulation and the painter):\n", stem.c_str(),
              frames, out.width, out.height);
  for (size_t i = 0; i < d.size(); ++i) {
    const Drawing& x = d[i];
    const double rest = x.wall - x.cost.raster - x.cost.readback - x.cost.resolve;
    std::printf(
        "  %s: frame %6.2f (CPU %6.2f) = rasterizing %6.2f + read-back %5.2f + resolve %5.2f + rest %6.2f"
        " | against 4: max %3d, mean %.3f, pixels differing %5.2f %%\n",
        names[i], x.wall * ms, x.cpu * ms, x.cost.raster * ms, x.cost.readback * ms, x.cost.resolve * ms, rest * ms, x.maxDiff,
        x.sumDiff / channels, 100.0 * x.differing / frames);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string preamble = bench::csvPreamble(argc, argv);
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool antialiasing = std::erase(args, std::string("--antialiasing")) > 0;
  const bool rendersOnly = antialiasing || std::erase(args, std::string("--renders-only")) > 0;
  std::string csvPath;
  for (size_t i = 0; i < args.size();) {
    if (args[i] == "--csv" && i + 1 < args.size()) {
      csvPath = args[i + 1];
      args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
    } else if (args[i].rfind("--csv=", 0) == 0) {
      csvPath = args[i].substr(6);
      args.erase(args.begin() + static_cast<long>(i));
    } else if (args[i] == "--csv") {
      std::cerr << "--csv needs a file\n";
      return 2;
    } else {
      ++i;
    }
  }
  if (antialiasing) csvPath.clear();
  const std::string rigidreel = args.size() > 0 ? args[0] : "build/rigidreel";
  const std::string scene = args.size() > 1 ? args[1] : "scenes/three_collisions_poll.yaml";
  const std::string baseline = args.size() > 2 ? args[2] : "";
  fs::create_directories("out/bench");
  // each line as it comes: the lecture packs take minutes
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  // every timing, a row each (render/bench/README.md), kept until the run ends and written whole
  std::ostringstream csv;
  csv << "measure,scene,bodies,size,fps,frames,program,wall_s,cpu_s,wall_ms_per_frame,cpu_ms_per_frame,"
         "ratio_wall_to_ffmpeg_alone,ratio_cpu_to_ffmpeg_alone,peak_mb\n";
  // (a negative number: not measured, an empty cell)
  struct Row {
    std::string measure{}, scene{};
    long bodies = -1;
    std::string size{};
    double fps = -1.0;
    long frames = 0;
    std::string program{};
    double wall = -1.0, cpu = -1.0, ratioWall = -1.0, ratioCpu = -1.0, peakMb = -1.0;
  };
  auto number = [](double x) { return x >= 0.0 ? render::jobs::formatNumber(x) : std::string(); };
  auto row = [&](const Row& r) {
    csv << r.measure << ',' << r.scene << ',' << (r.bodies >= 0 ? std::to_string(r.bodies) : "") << ',' << r.size << ','
        << number(r.fps) << ',' << (r.frames > 0 ? std::to_string(r.frames) : "") << ',' << r.program << ',' << number(r.wall)
        << ',' << number(r.cpu) << ',' << (r.frames > 0 ? number(r.wall >= 0.0 ? 1000.0 * r.wall / r.frames : -1.0) : "") << ','
        << (r.frames > 0 ? number(r.cpu >= 0.0 ? 1000.0 * r.cpu / r.frames : -1.0) : "") << ',' << number(r.ratioWall) << ','
        << number(r.ratioCpu) << ',' << number(r.peakMb) << '\n';
  };
  std::vector<std::pair<std::string, std::string>> programs = {{"rigidreel", rigidreel}};
  if (!baseline.empty()) programs.push_back({"baseline", baseline});

  // start-up: `check` of one scene, the median of 21 runs
  const std::string checked = "scenes/poll_bar_impulse.yaml";
  for (const auto& [name, program] : programs) {
    if (rendersOnly) break;
    const double s = medianTime({program, "check", checked}, 21);
    row({.measure = "check_startup", .scene = fs::path(checked).stem().string(), .program = name, .wall = s});
    std::printf("%-9s check %s: %6.1f ms (median of 21)\n", name.c_str(), checked.c_str(), 1000.0 * s);
  }

  // the video pipeline: `path` at w × h, `seconds` s at 60 fps; its parts per frame, rigidreel's side
  // alone, ffmpeg alone on the same frames, and the whole render (with its peak memory)
  const double fps = 60.0;
  const std::string standIn = writeStandIn("out/bench/stand-in");
  auto pipeline = [&](const std::string& path, int w, int h, const std::string& seconds) {
    const std::string stem = fs::path(path).stem().string();
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    render::video::VideoRequest request;
    request.root = "out/bench/render";
    request.size = render::video::FrameSize{w, h};
    request.fps = fps;
    request.duration = std::stod(seconds);
    const render::video::RenderPlan plan = render::video::planVideos(
        [&](const std::string& variant) { return render::scene::readScene(sim::yaml::readSceneSource(path, variant)); }, request);
    const render::video::VideoOutput& out = plan.videos.front();
    const long frames = out.frameCount;
    const std::string raw = "out/bench/frames-" + size + ".rgba";
    if (antialiasing) return compareAntialiasing(plan.variants[out.variant], out, stem);
    const FrameParts parts = measureParts(plan.variants[out.variant], out, raw);

    const std::vector<std::string> render{"",      "render", path,         "-o",    "out/bench/render", "--size", size,
                                          "--fps", "60",     "--duration", seconds, "--quiet"};
    auto renderWith = [&](const std::string& program) {
      std::vector<std::string> a = render;
      a[0] = program;
      return a;
    };
    // ffmpeg alone, with the arguments rigidreel gives it, on the same frames read from a file
    std::vector<std::string> encode{"ffmpeg"};
    for (const std::string& a :
         render::video::ffmpegArguments(render::video::VideoFormat::Mp4, w, h, fps, "out/bench/ffmpeg-only.mp4"))
      encode.push_back(a == "pipe:0" ? raw : a);
    // the whole render, its peak resident memory measured by GNU time (kB)
    struct Whole {
      std::string name;
      Timed timed;
      double peakMb;
    };
    std::vector<Whole> wholes;
    for (const auto& [name, program] : programs) wholes.push_back({name, {}, 0.0});
    // the same frames make the same video: the frames measured here are the ones rendered (this
    // build's video, compared before a baseline's, which may draw otherwise, takes its place)
    const std::string mp4 = "out/bench/render/" + stem + "/" + stem + ".mp4";
    bool same = true;
    // rounds in turn, each measure the median of its rounds: a short clip's ratio moved by a tenth
    // from one run to the next on an idle machine
    std::vector<Timed> sides, ffmpegs;
    std::vector<std::vector<Timed>> wholeRounds(programs.size());
    for (int round = 0; round < kRounds; ++round) {
      // rigidreel's side alone: its frames into the stand-in that discards them
      sides.push_back(timeWithPath(renderWith(rigidreel), standIn));
      ffmpegs.push_back(timeProgram(encode));
      for (size_t p = 0; p < programs.size(); ++p) {
        std::vector<std::string> timed{"/usr/bin/time", "-f", "%M", "-o", "out/bench/peak.txt"};
        for (const std::string& a : renderWith(programs[p].second)) timed.push_back(a);
        // (the last round's video gone first: a render that fails leaves none to compare)
        if (p == 0) fs::remove(mp4);
        wholeRounds[p].push_back(timeProgram(timed));
        wholes[p].peakMb = std::max(wholes[p].peakMb, std::atof(fileText("out/bench/peak.txt").c_str()) / 1024.0);
        if (p == 0)
          same = same && wholeRounds[p].back().status == 0 && fs::exists(mp4) &&
                 fileText(mp4) == fileText("out/bench/ffmpeg-only.mp4");
      }
    }
    const Timed side = median(sides), ffmpeg = median(ffmpegs);
    for (size_t p = 0; p < programs.size(); ++p) wholes[p].timed = median(wholeRounds[p]);
    fs::remove(raw);

    const long bodies = static_cast<long>(plan.variants[out.variant].scene.model.bodies.size());
    auto part = [&](const char* measure, const std::string& program, double wall, double cpu = -1.0) {
      row({.measure = measure,
           .scene = stem,
           .bodies = bodies,
           .size = size,
           .fps = fps,
           .frames = frames,
           .program = program,
           .wall = wall,
           .cpu = cpu});
    };
    part("simulation", "rigidreel", parts.simulation * frames / 1000.0);
    part("drawing", "rigidreel", parts.drawing * frames / 1000.0);
    part("readback", "rigidreel", parts.readback * frames / 1000.0);
    part("handover", "rigidreel", parts.handover * frames / 1000.0);
    part("render_into_discarding_reader", "rigidreel", side.seconds, side.cpu);
    part("ffmpeg_alone", "ffmpeg", ffmpeg.seconds, ffmpeg.cpu);
    const double perFrame = 1000.0 / frames;
    std::printf("\n%s, %ld frames of %s (%zu bodies), ms per frame:\n", size.c_str(), frames, stem.c_str(),
                plan.variants[out.variant].scene.model.bodies.size());
    std::printf("  simulation %6.2f | drawing %6.2f | read-back %5.2f | handing over %5.2f | encoding (ffmpeg alone) %6.2f\n",
                parts.simulation, parts.drawing, parts.readback, parts.handover, ffmpeg.seconds * perFrame);
    std::printf("  rigidreel's side into a discarding reader: %6.2f (CPU %.2f)\n", side.seconds * perFrame, side.cpu * perFrame);
    for (const Whole& whole : wholes) {
      row({.measure = "whole_render",
           .scene = stem,
           .bodies = bodies,
           .size = size,
           .fps = fps,
           .frames = frames,
           .program = whole.name,
           .wall = whole.timed.seconds,
           .cpu = whole.timed.cpu,
           .ratioWall = whole.timed.seconds / ffmpeg.seconds,
           .ratioCpu = whole.timed.cpu / ffmpeg.cpu,
           .peakMb = whole.peakMb});
      std::printf("  %-9s whole render %6.2f (%5.1f frames/s, peak %6.1f MB), %.2f x ffmpeg alone (CPU time: %.2f x)\n",
                  whole.name.c_str(), whole.timed.seconds * perFrame, frames / whole.timed.seconds, whole.peakMb,
                  whole.timed.seconds / ffmpeg.seconds, whole.timed.cpu / ffmpeg.cpu);
    }
    std::printf("  rigidreel's video is ffmpeg alone's, byte for byte: %s\n", same ? "yes" : "NO");
  };
  // the two-body poll at 720p and 1080p, 2 s
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}})
    if (w == 1280 || !rendersOnly) pipeline(scene, w, h, "2");
  // Box2D's pyramid (stack_layouts.h), resting, soft_step, 0.5 s at 720p: base 20 (210 boxes) and
  // base 100 (5,050 boxes), how the cost grows with the bodies.
  // Each on the bench's 1 m box ground and on a half-plane floor, as users write a floor: the box
  // ground bounds the automatic camera's view at its own width (the boxes a few pixels across),
  // the half-plane leaves it to the pile (the boxes as large as the frame allows), which costs more
  for (const bool halfPlane : {false, true})
    for (int base : {20, 100}) {
      const std::string stem = "pyramid" + std::to_string(base) + (halfPlane ? "_on_plane" : "");
      const std::string path = "out/bench/" + stem + ".yaml";
      std::ofstream yaml(path);
      yaml << "name: " << stem << "\nduration: 0.5\nworld: {gravity: [0, -10], friction: 0.6}\n"
           << "sim: {collisions: soft_step, dt: 0.016666666666666667}\nbodies:\n";
      if (halfPlane) yaml << "  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n";
      else
        yaml << "  - {name: ground, shape: {box: [" << std::max(80, 2 * base + 40)
             << ", 1]}, position: [0, -0.5], static: true}\n";
      for (int r = 0; r < base; ++r)
        for (int j = 0; j < base - r; ++j)
          yaml << "  - {name: b" << r << '_' << j << ", shape: {box: [1, 1]}, position: [" << -7.0 + 0.5625 * r + 1.125 * j
               << ", " << 0.5 + r << "]}\n";
      yaml.close();
      pipeline(path, 1280, 720, "0.5");
    }

  // the lecture pack (scenes/lecture, as `make lecture` makes it)
  std::printf("\n");
  for (const auto& [name, program] : programs) {
    if (rendersOnly) break;
    const std::string dir = "out/bench/lecture-" + name;
    fs::remove_all(dir);
    const Timed t = timeProgram({program, "lecture", "scenes/lecture", "-o", dir, "--quiet"});
    row({.measure = "lecture_pack", .scene = "scenes/lecture", .program = name, .wall = t.seconds, .cpu = t.cpu});
    std::printf("%-9s lecture pack: %6.1f s (CPU time %6.1f s)\n", name.c_str(), t.seconds, t.cpu);
  }
  if (!csvPath.empty() && !bench::writeCsv(csvPath, preamble + csv.str())) return 1;
  return 0;
}

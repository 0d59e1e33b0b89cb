#include "render/cli/output.h"

#include <ext/stdio_sync_filebuf.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>

#include "render/cli/commands.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/output_rules.h"
#include "render/scene/render_def.h"
#include "render/video/output_names.h"

namespace render::cli {
using namespace render::jobs;
using render::video::timeForName;

render::video::FrameSize parseSize(const std::string& text, const std::string& option) {
  static const std::regex form(R"((\d{1,6})[xX](\d{1,6}))");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw UsageError(option + ": expected WIDTHxHEIGHT in pixels, e.g. 1280x720, got '" + text + "'");
  const render::video::FrameSize s{std::stoi(m[1]), std::stoi(m[2])};
  const auto inRange = [](int v) { return v >= render::scene::kMinFrameSide && v <= render::scene::kMaxFrameSide; };
  if (!inRange(s.width) || !inRange(s.height))
    throw UsageError(option + ": each side must be from " + std::to_string(render::scene::kMinFrameSide) + " to " +
                     std::to_string(render::scene::kMaxFrameSide) + " pixels, got " + text);
  if (s.width % 2 || s.height % 2)
    throw UsageError(option + ": sides must be even (H.264 video halves the color planes); try " +
                     std::to_string(s.width + s.width % 2) + "x" + std::to_string(s.height + s.height % 2));
  return s;
}

void checkFps(double fps, const std::string& option) {
  if (!(fps > 0.0) || !(fps <= render::scene::kMaxFps))
    throw UsageError(option + ": frames per second must be above 0 and at most 1000, got " + render::jobs::formatNumber(fps));
}

render::jobs::AtomicFile openOutput(const std::string& path, const std::string& option) {
  try {
    return render::jobs::AtomicFile(path);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw UsageError(option + ": " + e.what());
  }
}

bool namesStandardOutput(const std::string& path) {
  return path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1";
}

void refuseInputAsOutput(const std::string& output, const std::string& input, const std::string& option,
                         const std::string& what) {
  refuseOutputs({{output, option}}, {{input, what}});
}

void refusePrintedOutputs(const std::string& output, const std::string& trace, bool quiet, const std::vector<std::string>& scenes,
                          const std::string& junit) {
  std::vector<PlannedOutput> outputs;
  // what standard output is redirected to (> FILE) is written too: not the trace, not a scene
  if (output.empty() && !quiet) outputs.push_back({"/dev/stdout", "standard output"});
  outputs.push_back({output, "-o"});
  if (!namesStandardOutput(trace)) outputs.push_back({trace, "--trace"});
  outputs.push_back({junit, "--junit"});
  std::vector<RunInput> inputs;
  for (const std::string& s : scenes) inputs.push_back({s});
  refuseOutputs(outputs, inputs);
}

std::string videoDiverged(const std::string& file, const render::video::VariantDiverged& d) {
  return file + ": the simulation diverged at t = " + timeForName(d.time) + ": body '" + d.model.bodies[d.body].name +
         "' has a non-finite state; try a smaller step (--dt " + timeForName(d.model.dt / 4) +
         ") or another integrator (--integrator rk4)\n";
}

std::unique_ptr<render::jobs::AtomicFile> openStaged(const std::string& path, const std::string& option) {
  try {
    return std::make_unique<render::jobs::AtomicFile>(path);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw UsageError(option + ": " + e.what());
  }
}

std::unique_ptr<render::jobs::AtomicFile> openTrace(const std::string& path) {
  if (namesStandardOutput(path)) return nullptr;
  return openStaged(path, "--trace");
}

std::ostream& traceStream(const std::unique_ptr<render::jobs::AtomicFile>& file) {
  if (file) return file->stream();
  // standard output itself, not std::cout, which -q silences and -o sends to a file; unbuffered
  // through C's stdout, as std::cout is, so what both print stays in order
  static __gnu_cxx::stdio_sync_filebuf<char> buffer(stdout);
  static std::ostream standardOutput(&buffer);
  return standardOutput;
}

}  // namespace render::cli

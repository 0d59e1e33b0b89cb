// What `render`, `snapshot` and `lecture` share: checking their command-line values (a bad one is
// a UsageError, exit 2), and what they say when a simulation diverges.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/jobs/atomic_file.h"
#include "render/jobs/exit_status.h"
#include "render/video/render_plan.h"
#include "render/trace/trace_writer.h"

namespace render::cli {

// "WxH": even sides from render::scene::kMinFrameSide to render::scene::kMaxFrameSide pixels; throws UsageError
render::video::FrameSize parseSize(const std::string& text, const std::string& option = "--size");
// frames per second above 0 and at most render::scene::kMaxFps; throws UsageError
void checkFps(double fps, const std::string& option = "--fps");

// an output file opened before the runs that fill it, so that a folder that cannot be written
// fails at once: throws UsageError naming the option
render::jobs::AtomicFile openOutput(const std::string& path, const std::string& option = "-o");

// the same, owned: for an output opened only when asked for (--junit FILE)
std::unique_ptr<render::jobs::AtomicFile> openStaged(const std::string& path, const std::string& option);

// /dev/stdout (or /dev/fd/1, /proc/self/fd/1): written to standard output itself, in order with
// what else is printed there (opened again, a regular file behind it would be written from its start)
bool namesStandardOutput(const std::string& path);

// an output file that is the run's input (the scene named as --trace) would be destroyed by the
// run: throws UsageError naming the option and what the input is ("the scene file")
void refuseInputAsOutput(const std::string& output, const std::string& input, const std::string& option,
                         const std::string& what = "the scene file");

// the one rule (render/jobs/output_rules.h) for the commands that print (simulate, check): -o,
// --trace and check's --junit neither a scene nor each other nor where standard output is
// redirected; throws UsageError
void refusePrintedOutputs(const std::string& output, const std::string& trace, bool quiet, const std::vector<std::string>& scenes,
                          const std::string& junit = {});

// "<file>: the simulation diverged at t = …: body '…' has a non-finite state; try a smaller step
// (--dt …) or another integrator (--integrator rk4)", a line, as `render` says it
std::string videoDiverged(const std::string& file, const render::video::VariantDiverged& d);

// `--trace FILE` of simulate, render and snapshot: the file staged, named only once it is whole, or
// none for standard output (namesStandardOutput), written as it goes; throws UsageError when it
// cannot be created
std::unique_ptr<render::jobs::AtomicFile> openTrace(const std::string& path);
// where a trace opened by openTrace goes: its file, or standard output
std::ostream& traceStream(const std::unique_ptr<render::jobs::AtomicFile>& file);

// `write(trace)` with the trace of `plan`'s one variant written to `path` (none when empty), the
// file named only when the writing succeeded
template <class Trace, class Plan, class Write>
void traced(const std::string& path, const Plan& plan, Write&& write) {
  if (path.empty()) return write(static_cast<Trace*>(nullptr));
  if (plan.variants.size() != 1)
    throw render::jobs::UsageError("--trace: a trace is one variant's run; choose one with --variant");
  const std::unique_ptr<render::jobs::AtomicFile> file = openTrace(path);
  Trace trace(traceStream(file), plan.variants.front().scene.model);
  write(&trace);
  if (file) file->commit();
}

}  // namespace render::cli

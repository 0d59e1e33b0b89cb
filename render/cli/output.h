// What `render`, `snapshot` and `lecture` share: checking their command-line values (a bad one is
// a UsageError, exit 2), and what they say when a simulation diverges.
#pragma once

#include <string>

#include "render/jobs/atomic_file.h"
#include "render/video/render_plan.h"

namespace render::cli {

// "WxH": even sides from render::scene::kMinFrameSide to render::scene::kMaxFrameSide pixels; throws UsageError
render::video::FrameSize parseSize(const std::string& text, const std::string& option = "--size");
// frames per second above 0 and at most render::scene::kMaxFps; throws UsageError
void checkFps(double fps, const std::string& option = "--fps");

// an output file opened before the runs that fill it, so that a folder that cannot be written
// fails at once: throws UsageError naming the option
render::jobs::AtomicFile openOutput(const std::string& path, const std::string& option = "-o");

// /dev/stdout (or /dev/fd/1, /proc/self/fd/1): written to standard output itself, in order with
// what else is printed there (opened again, a regular file behind it would be written from its start)
bool namesStandardOutput(const std::string& path);

// an output file that is the run's input (the scene named as --trace) would be destroyed by the
// run: throws UsageError naming the option
void refuseInputAsOutput(const std::string& output, const std::string& input, const std::string& option);

// "<file>: the simulation diverged at t = …: body '…' has a non-finite state; try a smaller step
// (--dt …) or another integrator (--integrator rk4)", a line, as `render` says it
std::string videoDiverged(const std::string& file, const render::video::VariantDiverged& d);

}  // namespace render::cli

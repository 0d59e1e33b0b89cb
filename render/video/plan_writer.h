// The render plan carried out: its directory created, each video recorded with its poster, then the
// stills, every file complete before it is named (PNGs renamed into place, ffmpeg's output renamed
// when it has finished well, frames in a hidden directory renamed at the end). A 3D plan is written by the same code, its
// frames drawn in perspective.
#pragma once

#include <functional>
#include <string>

#include "render/video/render_plan.h"
#include "render/trace/trace_writer.h"

namespace render::video {

// told the path of each output file (or frames directory) once it is complete
using Wrote = std::function<void(const std::string& path)>;

// `dir`, created when missing; throws UsageError naming `option` (-o, --plot) when it cannot be
// created or written
void createOutputDirectory(const std::string& dir, const std::string& option = "-o");

// writes every output of `plan`, in the order of plan.paths(), telling `wrote` each; without
// `quiet`, a progress bar per video and a summary of each on standard output. Throws UsageError (a
// directory that cannot be created or written), VariantDiverged, std::runtime_error (ffmpeg) and
// Interrupted (between frames). `trace` (when given) is told every step of the run the plan's one
// variant is drawn from (its video's, else its first still's), taken on to the variant's end: what
// `simulate --trace` writes of the same run
void writePlan(const RenderPlan& plan, bool quiet, const Wrote& wrote, render::trace::TraceWriter* trace = nullptr);
// the same for a 3D scene's plan, with VariantDiverged3d for a divergence
void writePlan3d(const RenderPlan3d& plan, bool quiet, const Wrote& wrote, render::trace::TraceWriter3d* trace = nullptr);

}  // namespace render::video

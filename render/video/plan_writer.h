// The render plan carried out: its directory created, each video recorded with its poster, then the
// stills, every file complete before it is named (PNGs renamed into place, ffmpeg's output renamed
// when it has finished well, frames in a hidden directory renamed at the end).
#pragma once

#include <functional>
#include <string>

#include "render/video/render_plan.h"

namespace render::video {

// told the path of each output file (or frames directory) once it is complete
using Wrote = std::function<void(const std::string& path)>;

// writes every output of `plan`, in the order of plan.paths(), telling `wrote` each; without
// `quiet`, a progress bar per video and a summary of each on standard output. Throws UsageError (a
// directory that cannot be created or written), VariantDiverged, std::runtime_error (ffmpeg) and
// Interrupted (between frames)
void writePlan(const RenderPlan& plan, bool quiet, const Wrote& wrote);

}  // namespace render::video

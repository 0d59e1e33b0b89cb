// `render` and `snapshot --overlay THEIRS.csv`: another simulator's trace drawn over each frame,
// read against each variant's bodies (a row for a body the variant lacks is bad input at its line).
#pragma once

#include <string>

#include "render/video/render_plan.h"

namespace render::cli {

// `load` with the trace in `path` set as each variant's overlay ("" : `load` itself)
render::video::LoadVariant withOverlay(render::video::LoadVariant load, const std::string& path);

}  // namespace render::cli

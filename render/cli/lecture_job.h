// One job of `rigidreel lecture`, in this process: a scene's videos and posters, as
// `render --all-variants` writes them, then the poll panels its `panels` key asks for, as
// `snapshot --panels` writes them.
#pragma once

#include <optional>
#include <string>

#include "render/cli/lecture_plan.h"
#include "render/cli/videos.h"

namespace render::cli {

struct LectureOptions {
  std::string output = "out/lecture";
  std::string size;          // "WxH", or empty for the scene's
  std::optional<double> fps;
  bool quiet = false;
};

// tells `wrote` each file once complete; kExitOk, or kExitFailure after saying why on standard
// error (the simulation diverged); throws as renderVideos and writeSnapshots do
int runLectureJob(const LecturePlan& plan, const LectureOptions& options, const Wrote& wrote);

}  // namespace render::cli

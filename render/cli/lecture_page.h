// The page's side of `rigidreel lecture` (render/page): each job leaves its scene's record beside
// its outputs, DIR/<scene>/page.json (what it rendered, the closed-form checks with the values the
// run measured, how long it took); then the page, DIR/index.html, is rebuilt from every record the
// folder holds, which `--page DIR` does alone.
#pragma once

#include <string>

#include "render/cli/lecture_job.h"
#include "render/cli/lecture_plan.h"

namespace render::cli {

// DIR/<scene>/page.json, the record a scene's job writes last
std::string lectureRecordPath(const LecturePlan& plan, const std::string& root);
// DIR/index.html
std::string lecturePagePath(const std::string& root);

// writes the scene's record for a job that rendered every output of `plan` in `seconds` (the videos
// at the options' frame rate, or the scene's), checking each variant's `expect` entries; tells `wrote`
void writeLectureRecord(const LecturePlan& plan, const LectureOptions& options, double seconds, const Wrote& wrote);

// the page rebuilt from the records in `root`: "page: DIR/index.html (N scenes)" on standard
// output, or why not on standard error. Returns whether it was written
bool rebuildLecturePage(const std::string& root);

}  // namespace render::cli

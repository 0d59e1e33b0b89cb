// What `golden check` leaves for people and for CI: an HTML page with, for each frame whose pixels
// differ, the expected, actual and diff images side by side with the numbers, and a JUnit XML file
// (one testcase per scene and level, a failure with its message; skipped levels as skipped).
#pragma once

#include <string>
#include <vector>

#include "render/golden/golden_check.h"

namespace render::golden {

// DIR/index.html and its images (DIR/<case>/<frame>-expected|actual|diff.png), the folder replaced
// whole; throws std::runtime_error
void writeReport(const std::vector<CaseResult>& results, const std::string& dir);
// the JUnit XML, written under a temporary name and renamed; throws std::runtime_error
void writeJunit(const std::vector<CaseResult>& results, const std::string& path);

}  // namespace render::golden

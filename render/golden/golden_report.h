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

// one JUnit testcase of any command (`check` writes one per scene variant)
struct JunitCase {
  std::string classname, name, file;
  LevelResult::Status status = LevelResult::Status::Ok;
  std::string message;  // the failure's or the skip's
};
// the same XML of `cases`, its suite named `suite` ("rigidreel check"); throws std::runtime_error
void writeJunit(const std::vector<JunitCase>& cases, const std::string& suite, const std::string& path);

}  // namespace render::golden

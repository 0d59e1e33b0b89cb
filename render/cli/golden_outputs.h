// What `golden record` and `golden check` write, put to output_rules.h's one rule before anything
// runs: record folders (one per scene variant, none shared, none holding a scene), the --report
// folder and the --junit file (neither a scene nor a record).
#pragma once

#include <string>
#include <vector>

namespace render::cli {

// one scene variant as golden names its record
struct GoldenCase {
  std::string file;     // the scene file
  std::string variant;  // "" for the base scene
  std::string name;     // "<scene>[-<variant>]": its record's folder
};

// golden record -o DIR; throws UsageError
void refuseRecordOutputs(const std::vector<GoldenCase>& cases, const std::string& dir);
// golden check --golden DIR --report REPORT --junit JUNIT [--update]; throws UsageError
void refuseCheckOutputs(const std::vector<GoldenCase>& cases, const std::string& golden, const std::string& report,
                        const std::string& junit, bool update);

}  // namespace render::cli

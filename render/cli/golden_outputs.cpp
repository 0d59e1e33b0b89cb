#include "render/cli/golden_outputs.h"

#include <filesystem>

#include "render/jobs/output_rules.h"

namespace render::cli {
using render::jobs::PlannedOutput;
using render::jobs::RunInput;

namespace {

std::vector<RunInput> scenesOf(const std::vector<GoldenCase>& cases) {
  std::vector<RunInput> inputs;
  for (const GoldenCase& c : cases) inputs.push_back({c.file, "the scene file"});
  return inputs;
}

// each variant's record folder, replaced whole when `written`
std::vector<PlannedOutput> recordFolders(const std::vector<GoldenCase>& cases, const std::string& dir, const std::string& option,
                                         bool written) {
  std::vector<PlannedOutput> outputs;
  for (const GoldenCase& c : cases)
    outputs.push_back({(std::filesystem::path(dir) / c.name).string(), option,
                       written ? PlannedOutput::Kind::Folder : PlannedOutput::Kind::Into, "golden record",
                       "the record of " + c.file + (c.variant.empty() ? "" : " (variant " + c.variant + ")")});
  return outputs;
}

}  // namespace

void refuseRecordOutputs(const std::vector<GoldenCase>& cases, const std::string& dir) {
  render::jobs::refuseOutputs(recordFolders(cases, dir, "-o", true), scenesOf(cases));
}

void refuseCheckOutputs(const std::vector<GoldenCase>& cases, const std::string& golden, const std::string& report,
                        const std::string& junit, bool update) {
  // the records are read: neither the report nor the JUnit file may be or hold one
  std::vector<RunInput> inputs = scenesOf(cases);
  for (const PlannedOutput& r : recordFolders(cases, golden, "--golden", false)) inputs.push_back({r.path, "the golden record"});
  render::jobs::refuseOutputs({{report, "--report", PlannedOutput::Kind::Folder, "golden report", "the report"},
                               {junit, "--junit", PlannedOutput::Kind::File, "", "the JUnit file"}},
                              inputs);
  // --update replaces the records that differ; two variants never share one
  render::jobs::refuseOutputs(recordFolders(cases, golden, "--golden", update), scenesOf(cases));
}

}  // namespace render::cli

// `rigidreel golden record | check`: golden records of anyone's scenes (render/golden), one folder
// per scene variant, and the scenes checked against them level by level, with an HTML report and
// JUnit XML for CI.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/golden_outputs.h"
#include "render/cli/lecture_files.h"
#include "render/cli/scene_options.h"
#include "render/golden/golden_check.h"
#include "render/golden/golden_record.h"
#include "render/golden/golden_report.h"
#include "render/golden/sha256.h"
#include "render/jobs/interrupt.h"
#include "render/video/output_names.h"

namespace render::cli {
using namespace render::golden;
using namespace render::jobs;

namespace {

namespace fs = std::filesystem;

struct RecordCommand {
  std::vector<std::string> scenes;
  std::string output = "golden";
};

struct CheckCommand {
  std::vector<std::string> scenes;
  std::string golden = "golden";
  std::string report;
  std::string junit;
  bool update = false;
  bool strict = false;
};

// one scene variant as golden reads it: the file's, with its golden: block
struct Case {
  std::string file;
  SceneFile scene;
};

// every variant of every file (the base scene when it has none), each read and its world started
// (bad input is exit 2 before anything runs); a 3D scene of a directory is skipped, said on stderr
std::vector<Case> casesOf(const std::vector<std::string>& arguments) {
  std::vector<Case> cases;
  std::vector<std::string> named;  // the files named themselves, not found in a directory
  for (const std::string& a : arguments)
    if (!fs::is_directory(a)) named.push_back(a);
  for (const std::string& file : lectureSceneFiles(arguments)) {
    const OpenScene opened(file);
    if (opened.is3d()) {
      if (std::find(named.begin(), named.end(), file) != named.end())
        throw UsageError(file + ": a 3D scene; golden records are of 2D scenes for now");
      std::cerr << file << ": skipped: a 3D scene, and golden records are of 2D scenes for now\n";
      continue;
    }
    (void)opened.read();  // the base scene read whole, as each variant is
    std::vector<std::string> variants = opened.variantNames();
    if (variants.empty()) variants.push_back("");
    for (const std::string& v : variants) {
      SceneFile scene = opened.read(v);
      (void)startWorld(scene.model(), file);
      cases.push_back({file, std::move(scene)});
    }
  }
  return cases;
}

// how the outputs name each case
std::vector<GoldenCase> namesOf(const std::vector<Case>& cases) {
  std::vector<GoldenCase> names;
  for (const Case& c : cases) names.push_back({c.file, c.scene.model().variant, render::video::outputBase(c.scene.model())});
  return names;
}

// the scene variant recorded as golden wants it into `dir`
GoldenRun record(const Case& c, const std::string& dir) {
  const GoldenRun run = runGolden(c.scene.scene, c.scene.golden, goldenTimes(c.scene.scene, c.scene.golden), true);
  writeRecord(run, {c.file, fileSha256(c.file), c.scene.golden}, dir);
  return run;
}

// "1 frame", "2 frames"
std::string count(size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::string describeRecord(const GoldenRun& run, const std::string& dir) {
  return (fs::path(dir) / run.name).string() + ": " + count(run.checkpoints.size(), "checkpoint") + ", " +
         count(run.frames.size(), "frame") + " (" + run.renderer + ")";
}

int recordAll(const RecordCommand& o) {
  const std::vector<Case> cases = casesOf(o.scenes);
  refuseRecordOutputs(namesOf(cases), o.output);
  for (const Case& c : cases) std::cout << describeRecord(record(c, o.output), o.output) << '\n';
  return kExitOk;
}

// "rigidreel golden record FILE -o DIR", the command that makes the missing record
std::string recordCommand(const Case& c, const std::string& dir) {
  return "rigidreel golden record " + c.file + (dir == "golden" ? "" : " -o " + dir);
}

int checkAll(const CheckCommand& o) {
  const std::vector<Case> cases = casesOf(o.scenes);
  refuseCheckOutputs(namesOf(cases), o.golden, o.report, o.junit, o.update);
  // every record there before anything runs
  std::vector<GoldenRecord> records;
  for (const Case& c : cases) {
    const std::string folder = (fs::path(o.golden) / render::video::outputBase(c.scene.model())).string();
    if (!fs::exists(fs::path(folder) / "manifest.json"))
      throw UsageError(c.file + ": no golden record in " + folder + "; record it first: " + recordCommand(c, o.golden));
    records.push_back(readRecord(folder, c.scene.model()));
  }
  std::vector<CaseResult> results;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    // the run at the record's times, its tolerances the scene's own
    GoldenDef golden = c.scene.golden;
    golden.width = records[i].golden.width, golden.height = records[i].golden.height;
    const GoldenRun run = runGolden(c.scene.scene, golden, records[i].times, true);
    GoldenRecord& record = records[i];
    record.golden.tolerance = c.scene.golden.tolerance;
    record.golden.pixelTolerance = c.scene.golden.pixelTolerance;
    record.golden.pixelFraction = c.scene.golden.pixelFraction;
    CaseResult result = checkRun(run, record, o.strict);
    if (fileSha256(c.file) != record.sceneSha256) result.warnings.push_back(c.file + " changed since it was recorded");
    for (const LevelResult& l : result.levels)
      std::cout << result.name << "  " << levelName(l.level) << "  " << (l.failed() ? "FAIL  " : "") << l.message << '\n';
    for (const std::string& w : result.warnings) std::cerr << result.name << ": warning: " << w << '\n';
    results.push_back(std::move(result));
  }
  if (!o.report.empty()) {
    writeReport(results, o.report);
    std::cout << "report: " << (fs::path(o.report) / "index.html").string() << '\n';
  }
  if (!o.junit.empty()) {
    writeJunit(results, o.junit);
    std::cout << "junit: " << o.junit << '\n';
  }
  bool failed = false;
  for (size_t i = 0; i < cases.size(); ++i) {
    if (!results[i].failed()) continue;
    failed = true;
    if (!o.update) continue;
    std::string levels;
    for (const LevelResult& l : results[i].levels)
      if (l.failed()) levels += std::string(levels.empty() ? "" : ", ") + levelName(l.level);
    const GoldenRun run = record(cases[i], o.golden);
    std::cout << "updated " << describeRecord(run, o.golden) << "; replaced the record of "
              << count(records[i].times.checkpoints.size(), "checkpoint") << " and "
              << count(records[i].frameNames.size(), "frame") << " that differed in: " << levels << '\n';
  }
  if (failed && o.update) return kExitOk;
  return failed ? kExitFailure : kExitOk;
}

}  // namespace

void addGoldenCommand(CLI::App& app, int& exitCode) {
  CLI::App* golden = app.add_subcommand("golden", "golden records of scenes: record them, check scenes against them");
  golden->require_subcommand(1);

  auto r = std::make_shared<RecordCommand>();
  CLI::App* rec = golden->add_subcommand(
      "record", "record each scene variant's states, trace, draw lists and frames into DIR/<scene>[-<variant>]/");
  rec->add_option("scenes", r->scenes, "scene files (YAML) or directories of them")->required();
  rec->add_option("-o,--output", r->output, "the golden directory (default: golden)");
  rec->callback([r, &exitCode] { exitCode = runInterruptible("golden record", [&] { return recordAll(*r); }); });

  auto c = std::make_shared<CheckCommand>();
  CLI::App* chk = golden->add_subcommand("check", "run each scene variant again and compare it with its golden record");
  chk->add_option("scenes", c->scenes, "scene files (YAML) or directories of them")->required();
  chk->add_option("--golden", c->golden, "the golden directory (default: golden)");
  chk->add_option("--report", c->report, "write DIR/index.html with expected, actual and diff images of each failed frame");
  chk->add_option("--junit", c->junit, "write a JUnit XML file: one testcase per scene and level");
  chk->add_flag("--update", c->update, "record anew each scene variant that differs, saying what it replaced");
  chk->add_flag("--strict", c->strict, "compare pixels even when the record's renderer is another one");
  chk->callback([c, &exitCode] { exitCode = runInterruptible("golden check", [&] { return checkAll(*c); }); });
}

}  // namespace render::cli

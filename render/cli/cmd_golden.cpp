// `rigidreel golden record | check`: golden records of anyone's scenes, 2D and 3D (render/golden),
// one folder per scene variant, and the scenes checked against them level by level, with an HTML
// report and JUnit XML for CI.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <variant>

#include "render/cli/commands.h"
#include "render/cli/golden_outputs.h"
#include "render/cli/lecture_files.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/golden/golden_check.h"
#include "render/golden/golden_record.h"
#include "render/golden/golden_report.h"
#include "render/golden/golden_run3d.h"
#include "render/golden/record_restamp.h"
#include "render/golden/sha256.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/video/output_names.h"

namespace render::cli {
using namespace render::golden;
using namespace render::jobs;

namespace {

namespace fs = std::filesystem;

struct RecordCommand : Verbosity {
  std::vector<std::string> scenes;
  std::string output = "golden";
};

struct CheckCommand : Verbosity {
  std::vector<std::string> scenes;
  std::string golden = "golden";
  std::string report;
  std::string junit;
  bool update = false;
  bool strict = false;
};

// one scene variant as golden reads it: the file's, 2D or 3D, with its golden: block. What differs
// between the two is overloaded (runGolden, readRecord), so each use is one visit
struct Case {
  std::string file;
  std::variant<SceneFile, SceneFile3d> scene;

  const GoldenDef& golden() const {
    return std::visit([](const auto& f) -> const GoldenDef& { return f.golden; }, scene);
  }
  // "<scene>[-<variant>]", the record's folder
  std::string name() const {
    return std::visit([](const auto& f) { return render::video::outputBase(f.model().name, f.model().variant); }, scene);
  }
  // the run at `times` (the golden: block's own when none), frames at `golden`'s size
  GoldenRun run(const GoldenDef& golden, const GoldenTimes* times = nullptr) const {
    return std::visit([&](const auto& f) { return runGolden(f.scene, golden, times, true); }, scene);
  }
  GoldenRecord recordIn(const std::string& folder) const {
    return std::visit([&](const auto& f) { return readRecord(folder, f.model()); }, scene);
  }
};

// the variants of one file (the base scene when it has none), each read and its world started
template <class File>
void addCases(std::vector<Case>& cases, const std::string& file, const std::vector<std::string>& variantNames,
              const std::function<File(const std::string&)>& read, const std::function<void(const File&)>& start) {
  (void)read("");  // the base scene read whole, as each variant is
  std::vector<std::string> variants = variantNames;
  if (variants.empty()) variants.push_back("");
  for (const std::string& v : variants) {
    File scene = read(v);
    start(scene);
    cases.push_back({file, std::move(scene)});
  }
}

// every variant of every file, 2D and 3D (bad input is exit 2 before anything runs)
std::vector<Case> casesOf(const std::vector<std::string>& arguments) {
  std::vector<Case> cases;
  for (const std::string& file : lectureSceneFiles(arguments)) {
    const OpenScene opened(file);
    if (opened.is3d())
      addCases<SceneFile3d>(
          cases, file, opened.read3d().model().variantNames, [&](const std::string& v) { return opened.read3d(v); },
          [&](const SceneFile3d& f) { (void)startWorld3d(f.model(), file); });
    else
      addCases<SceneFile>(
          cases, file, opened.variantNames(), [&](const std::string& v) { return opened.read(v); },
          [&](const SceneFile& f) { (void)startWorld(f.model(), file); });
  }
  return cases;
}

// how the outputs name each case
std::vector<GoldenCase> namesOf(const std::vector<Case>& cases) {
  std::vector<GoldenCase> names;
  for (const Case& c : cases)
    names.push_back({c.file, std::visit([](const auto& f) { return f.model().variant; }, c.scene), c.name()});
  return names;
}

// the scene variant recorded as golden wants it into `dir`
GoldenRun record(const Case& c, const std::string& dir) {
  const GoldenRun run = c.run(c.golden());
  writeRecord(run, {c.file, fileSha256(c.file), c.golden()}, dir);
  return run;
}

// "1 frame", "2 frames"
std::string count(size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::string describeRecord(const GoldenRun& run, const std::string& dir) {
  return (fs::path(dir) / run.name).string() + ": " + count(run.checkpoints.size(), "checkpoint") + ", " +
         count(run.frames.size(), "frame") + " (" + run.renderer + ")";
}

// -v: each checkpoint's state hash and each frame's files, as the record holds them
void describeContents(const GoldenRun& run) {
  for (const Checkpoint& c : run.checkpoints) {
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", c.hash);
    std::cout << "  checkpoint t = " << formatNumber(c.t) << ": state hash " << hash << '\n';
  }
  for (const GoldenFrame& f : run.frames)
    std::cout << "  " << f.name << ".json" << (f.image.rgba.empty() ? "" : ", " + f.name + ".png") << '\n';
}

int recordAll(const RecordCommand& o) {
  const std::vector<Case> cases = casesOf(o.scenes);
  refuseRecordOutputs(namesOf(cases), o.output);
  const SilencedOutput quiet(o.quiet);
  for (const Case& c : cases) {
    const GoldenRun run = record(c, o.output);
    std::cout << describeRecord(run, o.output) << '\n';
    if (o.verbose) describeContents(run);
  }
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
    const std::string folder = (fs::path(o.golden) / c.name()).string();
    if (!fs::exists(fs::path(folder) / "manifest.json"))
      throw UsageError(c.file + ": no golden record in " + folder + "; record it first: " + recordCommand(c, o.golden));
    records.push_back(c.recordIn(folder));
  }
  std::vector<CaseResult> results;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    // the run at the record's times, its tolerances the scene's own
    GoldenDef golden = c.golden();
    golden.width = records[i].golden.width, golden.height = records[i].golden.height;
    const GoldenRun run = c.run(golden, &records[i].times);
    GoldenRecord& record = records[i];
    record.golden.tolerance = c.golden().tolerance;
    record.golden.pixelTolerance = c.golden().pixelTolerance;
    record.golden.pixelFraction = c.golden().pixelFraction;
    CaseResult result = checkRun(run, record, o.strict);
    const std::string sha = fileSha256(c.file);
    // --update: a variant that passes though its file changed keeps its record, stamped with the new sha256
    if (sha != record.sceneSha256 && o.update && !result.failed()) {
      restampRecord(record, {c.file, sha, record.golden});
      if (!o.quiet) std::cout << "restamped " << record.folder << ": " << c.file << " changed, this variant's run did not\n";
    } else if (sha != record.sceneSha256) {
      result.warnings.push_back(c.file + " changed since it was recorded");
    }
    if (o.verbose)
      std::cout << result.name << ": against " << record.folder << " (rigidreel " << record.version << ", " << record.renderer
                << ")\n";
    // --quiet: the failed levels alone
    for (const LevelResult& l : result.levels)
      if (!o.quiet || l.failed())
        std::cout << result.name << "  " << levelName(l.level) << "  " << (l.failed() ? "FAIL  " : "") << l.message << '\n';
    for (const std::string& w : result.warnings) std::cerr << result.name << ": warning: " << w << '\n';
    results.push_back(std::move(result));
  }
  if (!o.report.empty()) {
    writeReport(results, o.report);
    if (!o.quiet) std::cout << "report: " << (fs::path(o.report) / "index.html").string() << '\n';
  }
  if (!o.junit.empty()) {
    writeJunit(results, o.junit);
    if (!o.quiet) std::cout << "junit: " << o.junit << '\n';
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
  r->addTo(*rec, "print nothing (the records are still written); errors still on standard error",
           "also each checkpoint's state hash and each frame's files");
  rec->callback([r, &exitCode] { exitCode = runInterruptible("golden record", [&] { return recordAll(*r); }); });

  auto c = std::make_shared<CheckCommand>();
  CLI::App* chk = golden->add_subcommand("check", "run each scene variant again and compare it with its golden record");
  chk->add_option("scenes", c->scenes, "scene files (YAML) or directories of them")->required();
  chk->add_option("--golden", c->golden, "the golden directory (default: golden)");
  chk->add_option("--report", c->report, "write DIR/index.html with expected, actual and diff images of each failed frame");
  chk->add_option("--junit", c->junit, "write a JUnit XML file: one testcase per scene and level");
  chk->add_flag("--update", c->update, "record anew each scene variant that differs, saying what it replaced");
  chk->add_flag("--strict", c->strict, "compare pixels even when the record's renderer is another one");
  c->addTo(*chk, "only the failed levels (and what --update replaced); warnings and errors still on standard error",
           "also the record each variant is checked against: its folder, rigidreel version and renderer");
  chk->callback([c, &exitCode] { exitCode = runInterruptible("golden check", [&] { return checkAll(*c); }); });
}

}  // namespace render::cli

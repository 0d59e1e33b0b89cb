// `rigidreel lecture`: the course's whole pack of scenes, each scene's videos, posters and poll
// panels, one job per scene. Every scene file is checked before anything renders; then each job
// runs as a child process of this same program (`rigidreel lecture SCENE -j 1 ...`, so that one
// job is one command line, which GNU Parallel or a Slurm array can run as well), at most -j at a
// time, its output captured and reported when it ends. Each job leaves its scene's record for the
// page; the page, DIR/index.html, is rebuilt from the records the folder holds (lecture_page.h).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <thread>

#include "render/cli/commands.h"
#include "render/cli/lecture_job.h"
#include "render/cli/lecture_page.h"
#include "render/cli/lecture_summary.h"
#include "render/cli/output.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/job_runner.h"
#include "render/page/page.h"

namespace render::cli {
using namespace render::jobs;

namespace {

using Clock = std::chrono::steady_clock;

struct LectureCommand : LectureOptions {
  std::vector<std::string> paths;
  size_t jobs = std::max(1u, std::thread::hardware_concurrency());
  bool list = false;
  std::string page;  // --page DIR: only rebuild DIR's page
};

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// this program, to start the jobs with: /proc/self/exe survives a relative argv[0] and a changed PATH.
// A rebuild during the run replaces the file, and the link then reads "<path> (deleted)": the jobs
// start the new file at the same path
std::string selfPath() {
  std::error_code error;
  std::string self = std::filesystem::read_symlink("/proc/self/exe", error).string();
  if (error) return "rigidreel";
  const std::string deleted = " (deleted)";
  if (self.size() > deleted.size() && self.compare(self.size() - deleted.size(), deleted.size(), deleted) == 0)
    self.resize(self.size() - deleted.size());
  return self;
}

// the job's command line: the same options, -j 1, on one scene
std::vector<std::string> jobCommand(const LectureCommand& o, const std::string& file) {
  std::vector<std::string> argv = {selfPath(), "lecture", file, "-o", o.output, "-j", "1"};
  if (!o.size.empty()) argv.insert(argv.end(), {"--size", o.size});
  if (o.fps) {
    char fps[32];
    std::snprintf(fps, sizeof fps, "%.17g", *o.fps);
    argv.insert(argv.end(), {"--fps", fps});
  }
  if (o.quiet) argv.push_back("--quiet");
  return argv;
}

// one scene in this process; its failure is a result, not an exception, so that the table follows
SceneResult runHere(const LecturePlan& plan, const LectureOptions& o) {
  SceneResult r{plan.base.model.name, plan.file, false, {}, 0.0, {}};
  const auto start = Clock::now();
  try {
    const Wrote wrote = [&](const std::string& path) {
      std::cout << "wrote " << path << std::endl;
      r.outputs.push_back(path);
    };
    r.ok = runLectureJob(plan, o, wrote) == kExitOk;
    // the record last: the page shows a scene only once every file it names is there
    if (r.ok) writeLectureRecord(plan, o, since(start), wrote);
    if (!r.ok) r.message = "see the message above";
  } catch (const Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    std::cerr << "rigidreel: " << e.what() << '\n';
    r.message = e.what();
  }
  r.seconds = since(start);
  return r;
}

int lecture(const LectureCommand& o) {
  const auto start = Clock::now();
  if (!o.page.empty()) {
    if (!o.paths.empty()) throw UsageError("--page rebuilds the page of a pack already rendered; leave out the scenes");
    const size_t scenes = render::page::writePage(o.page);
    std::cout << "wrote " << lecturePagePath(o.page) << " (" << scenes << (scenes == 1 ? " scene" : " scenes") << ")\n";
    return kExitOk;
  }
  if (o.paths.empty()) throw UsageError("give scene files or directories of them (or --page DIR to rebuild a pack's page)");
  if (!o.size.empty()) parseSize(o.size);
  if (o.fps) checkFps(*o.fps);
  if (o.jobs < 1) throw UsageError("-j: run at least 1 job at a time");

  // every scene checked before anything renders: a bad file stops the whole pack (exit 2)
  std::vector<LecturePlan> plans;
  std::set<std::string> names;
  for (const std::string& file : lectureSceneFiles(o.paths)) {
    plans.push_back(planLecture(file));
    if (!names.insert(plans.back().base.model.name).second)
      throw UsageError(file + ": another file of the pack also names its scene '" + plans.back().base.model.name +
                       "'; their outputs would overwrite each other under " + o.output + "/; give it its own 'name:'");
  }
  if (o.list) {
    for (const LecturePlan& plan : plans) {
      for (const std::string& path : lectureOutputs(plan, o.output)) std::cout << path << '\n';
      std::cout << lectureRecordPath(plan, o.output) << '\n';
    }
    std::cout << lecturePagePath(o.output) << '\n';
    return kExitOk;
  }
  std::error_code error;
  std::filesystem::create_directories(o.output, error);
  if (error) throw UsageError("-o: cannot create " + o.output + " (" + error.message() + "); choose another with -o DIR");

  std::vector<SceneResult> results;
  size_t parallel = 1;
  if (plans.size() == 1) {
    results.push_back(runHere(plans.front(), o));
  } else {
    parallel = std::min(o.jobs, plans.size());
    std::vector<std::vector<std::string>> commands;
    for (const LecturePlan& plan : plans) commands.push_back(jobCommand(o, plan.file));
    results.resize(plans.size());
    size_t finished = 0;
    runJobs(commands, parallel, [&](const JobResult& job) {
      SceneResult& r = results[job.job];
      r = {plans[job.job].base.model.name, plans[job.job].file, succeeded(job), wroteLines(job.output), job.seconds, {}};
      r.message = job.errors.empty() ? describeStatus(job.status) : job.errors;
      ++finished;
      const std::string counter = "[" + std::to_string(finished) + "/" + std::to_string(plans.size()) + "] ";
      if (r.ok && !o.quiet)
        std::cout << counter << r.scene << ": " << r.outputs.size() << " outputs in " << secondsText(job.seconds) << " s" << std::endl;
      if (!r.ok)
        std::cerr << counter << r.scene << " FAILED (" << describeStatus(job.status) << "):\n" << indented(job.errors) << std::flush;
    });
  }
  // the page from every record in the folder, this run's and any other's (after a single scene, it
  // is this job's own last step, as under GNU Parallel or Slurm)
  const bool page = rebuildLecturePage(o.output);
  printLectureSummary(results, since(start), parallel, plans.size() == 1, page, std::cout, std::cerr);
  for (const SceneResult& r : results)
    if (!r.ok) return kExitFailure;
  return page ? kExitOk : kExitFailure;
}

}  // namespace

void addLectureCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<LectureCommand>();
  CLI::App* cmd = app.add_subcommand(
      "lecture", "a pack of scenes: every variant's video and poster and the poll panels, one job per scene");
  cmd->add_option("scenes", o->paths, "scene files (YAML) and directories of them (every *.yaml)");
  cmd->add_option("-o,--output", o->output, "the output directory (default: out/lecture)");
  cmd->add_option("-j,--jobs", o->jobs, "scenes rendered at a time (default: the number of cores)");
  cmd->add_option("--size", o->size, "frame size WIDTHxHEIGHT in pixels, even (default: each scene's)");
  cmd->add_option("--fps", o->fps, "frames per second (default: each scene's)");
  cmd->add_flag("--quiet", o->quiet, "no line per scene as it ends (the summary and failures stay)");
  cmd->add_flag("--list", o->list, "print the paths the pack would write, one a line, and render nothing");
  cmd->add_option("--page", o->page, "only rebuild DIR/index.html from the scenes DIR holds (after jobs run one by one)");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible([&] { return lecture(*o); }); });
}

}  // namespace render::cli

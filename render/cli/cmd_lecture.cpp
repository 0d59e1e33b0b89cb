// `rigidreel lecture`: the course's whole pack of scenes, each scene's videos, posters and poll
// panels, one job per scene. Every scene file is checked before anything renders; then each job
// runs as a child process of this same program (`rigidreel lecture SCENE -j 1 ...`, so that one
// job is one command line, which GNU Parallel or a Slurm array can run as well), at most -j at a
// time, its output captured and reported when it ends. Every scene's render plan (render_plan.h)
// is made before anything renders: --list prints its paths, a job writes them. Each job leaves its
// scene's record for the page; the page, DIR/index.html, is rebuilt from the records the folder
// holds (lecture_page.h).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <thread>

#include "render/cli/commands.h"
#include "render/cli/lecture_files.h"
#include "render/cli/lecture_page.h"
#include "render/cli/lecture_summary.h"
#include "render/cli/output.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/job_runner.h"
#include "render/page/page.h"
#include "render/video/output_names.h"
#include "render/video/plan_writer.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::video;

namespace {

using Clock = std::chrono::steady_clock;

struct LectureCommand : Verbosity {
  std::vector<std::string> paths;
  std::string output = "out/lecture";
  // signed: "-j -1" read into a size_t wrapped to 2⁶⁴ − 1 and passed as "unlimited"
  long jobs = std::max(1u, std::thread::hardware_concurrency());
  std::string size;  // "WxH", or empty for the scene's
  std::optional<double> fps;
  bool list = false;
  std::string page;   // --page DIR: only rebuild DIR's page
  std::string title;  // --title: the page's, kept in DIR/title.txt
};

// a scene of the pack, checked before anything renders: its plan, or the divergence of a simulation
// that stopped it, which the scene's job reports as it reports any failure
struct PackScene {
  std::string file;
  std::string name;
  render::scene::Scene base;  // without a variant: its title, description and `panels:`, for the page
  std::optional<RenderPlan> plan;
  std::exception_ptr diverged;
  // a 3D scene's (dimensions: 3), instead of `base` and `plan`
  std::optional<render::scene3d::Scene> base3d;
  std::optional<RenderPlan3d> plan3d;

  std::vector<std::string> paths() const { return plan3d ? plan3d->paths() : plan->paths(); }
  // what rendering it costs, roughly: the pixels of its frames and stills (0 when it diverged)
  double pixels() const {
    double sum = 0.0;
    const auto add = [&](const auto& plan) {
      for (const auto& v : plan.videos) sum += static_cast<double>(v.frameCount) * v.width * v.height;
      if (plan.stills)
        sum += static_cast<double>(plan.stills->shots.size() * plan.variants.size()) * plan.stills->width * plan.stills->height;
    };
    if (plan3d) add(*plan3d);
    if (plan) add(*plan);
    return sum;
  }
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

// the job's command line: the same options, -j 1, on one scene; the values joined to their options
// and the scene after "--", so that a path that starts with '-' is not read as an option
std::vector<std::string> jobCommand(const LectureCommand& o, const std::string& file) {
  std::vector<std::string> argv = {selfPath(), "lecture", "--output=" + o.output, "-j", "1"};
  if (!o.size.empty()) argv.insert(argv.end(), {"--size", o.size});
  if (o.fps) {
    char fps[32];
    std::snprintf(fps, sizeof fps, "%.17g", *o.fps);
    argv.insert(argv.end(), {"--fps", fps});
  }
  if (o.quiet) argv.push_back("--quiet");
  if (!o.title.empty()) argv.insert(argv.end(), {"--title", o.title});
  argv.insert(argv.end(), {"--", file});
  return argv;
}

// the scene's plan: its variants loaded and their worlds started, surveyed, its outputs named;
// throws sim::yaml::SceneError
PackScene planScene(LectureRequest request, const std::string& file) {
  request.file = file;
  PackScene scene;
  scene.file = file;
  const OpenScene opened(file);
  if (opened.is3d()) {
    const LoadVariant3d load = lectureLoader3d(opened);
    scene.base3d = load("");
    scene.name = scene.base3d->model.name;
    try {
      scene.plan3d = planLecture3d(load, request);
    } catch (const VariantDiverged3d&) {
      scene.diverged = std::current_exception();
    }
    return scene;
  }
  const LoadVariant load = lectureLoader(opened);
  scene.base = load("");
  try {
    scene.plan = planLecture(load, request);
    scene.name = scene.plan->scene;
  } catch (const VariantDiverged& d) {
    scene.name = d.model.name;
    scene.diverged = std::current_exception();
  }
  return scene;
}

// one scene in this process, as `render --all-variants` and `snapshot --panels` would write it,
// quietly; its failure is a result, not an exception, so that the table follows
SceneResult runHere(const PackScene& scene, const std::string& root) {
  SceneResult r{scene.name, scene.file, false, {}, 0.0, {}};
  const auto start = Clock::now();
  try {
    if (scene.diverged) std::rethrow_exception(scene.diverged);
    const auto wrote = [&](const std::string& path) {
      std::cout << "wrote " << path << std::endl;
      r.outputs.push_back(path);
    };
    // the record last: the page shows a scene only once every file it names is there
    if (scene.plan3d) {
      writePlan3d(*scene.plan3d, true, wrote);
      writeLectureRecord(*scene.plan3d, *scene.base3d, scene.file, root, since(start), wrote);
    } else {
      writePlan(*scene.plan, true, wrote);
      writeLectureRecord(*scene.plan, scene.base, scene.file, root, since(start), wrote);
    }
    r.ok = true;
  } catch (const VariantDiverged& d) {
    if (d.when == VariantDiverged::While::Stills)
      std::cerr << scene.file << ": the simulation diverged at t = " << timeForName(d.time)
                << "; try a smaller step (sim: {dt: ...}) or another integrator\n";
    else std::cerr << videoDiverged(scene.file, d);
    r.message = "see the message above";
  } catch (const VariantDiverged3d& d) {
    std::cerr << divergedMessage(scene.file, d.model, d) << '\n';
    r.message = "see the message above";
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
    if (!o.title.empty()) render::page::writePackTitle(o.page, o.title);
    const size_t scenes = render::page::writePage(o.page);
    std::cout << "wrote " << lecturePagePath(o.page) << " (" << scenes << (scenes == 1 ? " scene" : " scenes") << ")\n";
    return kExitOk;
  }
  if (o.paths.empty()) throw UsageError("give scene files or directories of them (or --page DIR to rebuild a pack's page)");
  LectureRequest request{.root = o.output, .file = {}, .size = {}, .fps = o.fps};
  if (!o.size.empty()) request.size = parseSize(o.size);
  if (o.fps) checkFps(*o.fps);
  if (o.jobs < 1) throw UsageError("-j: run at least 1 job at a time, got " + std::to_string(o.jobs));

  // every scene checked before anything renders: a bad file stops the whole pack (exit 2)
  std::vector<PackScene> scenes;
  std::set<std::string> names;
  for (const std::string& file : lectureSceneFiles(o.paths)) {
    scenes.push_back(planScene(request, file));
    if (!names.insert(scenes.back().name).second)
      throw UsageError(file + ": another file of the pack also names its scene '" + scenes.back().name +
                       "'; their outputs would overwrite each other under " + o.output + "/; give it its own 'name:'");
  }
  // the paths each job's plan writes
  if (o.list) {
    for (const PackScene& scene : scenes)
      if (scene.diverged) std::rethrow_exception(scene.diverged);
    for (const PackScene& scene : scenes) {
      for (const std::string& path : scene.paths()) std::cout << path << '\n';
      std::cout << lectureRecordPath(scene.name, o.output) << '\n';
    }
    std::cout << lecturePagePath(o.output) << '\n';
    return kExitOk;
  }
  std::error_code error;
  std::filesystem::create_directories(o.output, error);
  if (error) throw UsageError("-o: cannot create " + o.output + " (" + error.message() + "); choose another with -o DIR");
  if (!o.title.empty()) render::page::writePackTitle(o.output, o.title);

  std::vector<SceneResult> results;
  size_t parallel = 1;
  if (scenes.size() == 1) {
    results.push_back(runHere(scenes.front(), o.output));
  } else {
    parallel = std::min(static_cast<size_t>(o.jobs), scenes.size());
    // the scenes with the most pixels to draw and encode first (job_runner.h)
    std::vector<double> pixels;
    for (const PackScene& scene : scenes) pixels.push_back(scene.pixels());
    const std::vector<size_t> order = largestFirst(pixels);
    std::vector<std::vector<std::string>> commands;
    for (size_t i : order) commands.push_back(jobCommand(o, scenes[i].file));
    results.resize(scenes.size());
    size_t finished = 0;
    runJobs(commands, parallel, [&](const JobResult& job) {
      const size_t i = order[job.job];
      SceneResult& r = results[i];
      r = {scenes[i].name, scenes[i].file, succeeded(job), wroteLines(job.output), job.seconds, {}};
      r.message = job.errors.empty() ? describeStatus(job.status) : job.errors;
      ++finished;
      const std::string counter = "[" + std::to_string(finished) + "/" + std::to_string(scenes.size()) + "] ";
      if (r.ok && !o.quiet)
        std::cout << counter << r.scene << ": " << r.outputs.size() << " outputs in " << secondsText(job.seconds) << " s"
                  << std::endl;
      if (r.ok && o.verbose)
        for (const std::string& path : r.outputs) std::cout << "  wrote " << path << '\n';
      if (!r.ok)
        std::cerr << counter << r.scene << " FAILED (" << describeStatus(job.status) << "):\n"
                  << indented(job.errors) << std::flush;
    });
  }
  // the page from every record in the folder, this run's and any other's (after a single scene, it
  // is this job's own last step, as under GNU Parallel or Slurm)
  const bool page = rebuildLecturePage(o.output);
  printLectureSummary(results, since(start), parallel, scenes.size() == 1, page, std::cout, std::cerr);
  for (const SceneResult& r : results)
    if (!r.ok) return kExitFailure;
  return page ? kExitOk : kExitFailure;
}

}  // namespace

void addLectureCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<LectureCommand>();
  CLI::App* cmd =
      app.add_subcommand("lecture", "a pack of scenes: every variant's video and poster and the poll panels, one job per scene");
  cmd->add_option("scenes", o->paths, "scene files (YAML) and directories of them (every *.yaml)");
  cmd->add_option("-o,--output", o->output, "the output directory (default: out/lecture)");
  cmd->add_option("-j,--jobs", o->jobs, "scenes rendered at a time (default: the number of cores)");
  cmd->add_option(
      "--size", o->size,
      "frame size WIDTHxHEIGHT in pixels, even (default: each scene's), and the poll panel sheets' (default 1920x1080)");
  cmd->add_option("--fps", o->fps, "frames per second (default: each scene's)");
  o->addTo(*cmd, "no line per scene as it ends (the summary and failures stay)",
           "also every file each scene wrote, under its line");
  cmd->add_flag("--list", o->list, "print the paths the pack would write, one a line, and render nothing");
  cmd->add_option("--title", o->title,
                  "the page's title (default: \"Lecture pack\"; kept in DIR/title.txt for the jobs and --page)");
  cmd->add_option("--page", o->page, "only rebuild DIR/index.html from the scenes DIR holds (after jobs run one by one)");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("lecture", [&] { return lecture(*o); }); });
}

}  // namespace render::cli

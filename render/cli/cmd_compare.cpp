// `rigidreel compare`: another simulator's trajectory (a trace CSV on any time grid, the 3D columns
// for a 3D scene) against the scene's run, per body the largest error of position, angle and
// velocity and when each first exceeds its tolerance; with --plot an error-against-time chart.
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>

#include "render/analysis/chart.h"
#include "render/cli/commands.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/golden/trace_compare.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/video/output_names.h"
#include "render/video/plan_writer.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/scene_error.h"

namespace render::cli {
using namespace render::trace;
using namespace render::golden;
using namespace render::jobs;

namespace {

namespace fs = std::filesystem;

struct CompareCommand : SceneOptions, Verbosity {
  std::string trace;
  std::string tolerance;
  std::string plot;
};

// errors and times to 6 significant digits (the time of a step is a sum of dt: 1.0010000000000001)
std::string over(const ErrorTrack& e, double tolerance) {
  using render::video::timeForName;
  std::string s = timeForName(e.largest);
  if (e.largest > 0.0) s += " at t = " + timeForName(e.largestAt);
  if (e.firstOver >= 0.0) s += ", over " + formatNumber(tolerance) + " from t = " + timeForName(e.firstOver);
  return s;
}

// -v: each body's errors at every instant compared, one line each, as the chart draws them
void printErrors(const std::vector<BodyComparison>& bodies) {
  for (const BodyComparison& b : bodies)
    for (size_t k = 0; b.compared && k < b.positionErrors.size(); ++k)
      std::cout << "  " << b.name << " t = " << render::video::timeForName(b.positionErrors[k].first) << ": position "
                << formatNumber(b.positionErrors[k].second) << ", angle " << formatNumber(b.angleErrors[k].second)
                << ", velocity " << formatNumber(b.velocityErrors[k].second) << '\n';
}

// errors against time, one line per body and quantity, on a log scale (zero errors drawn at 1e-16)
void plot(const std::vector<BodyComparison>& bodies, const std::string& dir, const std::string& base, const std::string& theirs) {
  render::analysis::Chart chart;
  chart.title = base + ": error against " + fs::path(theirs).filename().string();
  chart.xLabel = "t (s)";
  chart.yLabel = "error (m, rad, m/s)";
  chart.logY = true;
  const auto floorOf = [](std::vector<std::pair<double, double>> points) {
    for (auto& p : points) p.second = std::max(p.second, 1e-16);
    return points;
  };
  for (const BodyComparison& b : bodies) {
    if (!b.compared) continue;
    chart.series.push_back({b.name + " position", floorOf(b.positionErrors), false});
    chart.series.push_back({b.name + " angle", floorOf(b.angleErrors), false});
    chart.series.push_back({b.name + " velocity", floorOf(b.velocityErrors), false});
  }
  const std::string path = (fs::path(dir) / (base + "-compare.png")).string();
  render::analysis::writeChart(chart, path);
  std::cout << "chart: " << path << '\n';
}

// the scene `def` (2D or 3D), its world started by `start`, against their trace: the trace read
// and compared by the overloads for its dimension
template <class Def, class World>
int compareWith(const CompareCommand& o, const Def& def, const std::function<World()>& start) {
  CompareTolerance tolerance;
  try {
    if (!o.tolerance.empty()) tolerance = parseCompareTolerance(o.tolerance);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--tolerance: ") + e.what());
  }
  // a chart's folder that cannot be made is bad input, said before the run
  if (!o.plot.empty()) render::video::createOutputDirectory(o.plot, "--plot");
  const Trace theirs = readTrace(o.trace, def);
  World world = start();
  const std::vector<BodyComparison> bodies = compareTrace(def, world, theirs, tolerance);
  // rows that meet none of our instants compare nothing: "ok (t = 0 to 0)" passed a trace of t = 5 to 6
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].compared && bodies[i].positionErrors.empty()) {
      const std::vector<TraceSample>& rows = theirs.bodies[i];
      throw sim::yaml::SceneError(o.trace, rows.front().line, 1,
                                  "no row of '" + sim::yaml::shownName(def.bodies[i].name) + "' meets the run (t = 0 to " +
                                      formatNumber(def.duration) + " s, a step every " + formatNumber(def.dt) +
                                      " s): its rows run from t = " + formatNumber(rows.front().t) + " to " +
                                      formatNumber(rows.back().t) + "; give rows within the run");
    }
  const std::string base = render::video::outputBase(def.name, def.variant);
  // --quiet: the failed bodies alone
  std::ostream& out = o.quiet ? nowhere() : std::cout;
  out << base << " against " << o.trace << " (" << theirs.rows << " rows), tolerances: position "
      << formatNumber(tolerance.position) << " m, angle " << formatNumber(tolerance.angle) << " rad, velocity "
      << formatNumber(tolerance.velocity) << '\n';
  bool failed = false, any = false;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const BodyComparison& b = bodies[i];
    if (!b.compared) {
      if (!isStaticBody(def.bodies[i])) out << "  " << b.name << ": no rows in the trace, not compared\n";
      continue;
    }
    any = true;
    failed = failed || b.exceeded();
    (b.exceeded() ? std::cout : out) << (b.exceeded() ? "  FAIL  " : "  ok    ") << b.name
                                     << " (t = " << render::video::timeForName(b.from) << " to "
                                     << render::video::timeForName(b.to) << "): position " << over(b.position, tolerance.position)
                                     << "; angle " << over(b.angle, tolerance.angle) << "; velocity "
                                     << over(b.velocity, tolerance.velocity)
                                     << "; kinetic energy at t = " << render::video::timeForName(b.to) << ": ours "
                                     << formatNumber(b.oursEnergy) << " J, theirs " << formatNumber(b.theirsEnergy) << " J\n";
  }
  if (!any) throw UsageError(o.trace + ": no rows for any body of the scene");
  if (o.verbose) printErrors(bodies);
  if (!o.plot.empty()) {
    const SilencedOutput quiet(o.quiet);
    plot(bodies, o.plot, base, o.trace);
  }
  return failed ? kExitFailure : kExitOk;
}

int compare(const CompareCommand& o) {
  if (o.is3d()) {
    const sim::scene3d::SceneDef def = o.load3d().model();
    return compareWith<sim::scene3d::SceneDef, sim::world3d::World>(o, def, [&] { return startWorld3d(def, o.scene); });
  }
  const sim::scene::SceneDef def = o.load().model();
  return compareWith<sim::scene::SceneDef, sim::world::World>(o, def, [&] { return startWorld(def, o.scene); });
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<CompareCommand>();
  CLI::App* cmd = app.add_subcommand("compare", "compare another simulator's trace (CSV) with the scene's run");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->SceneOptions::addTo(*cmd);
  o->Verbosity::addTo(*cmd, "only the bodies that fail (the chart is still written); errors still on standard error",
                      "also each body's position, angle and velocity errors at every instant compared");
  cmd->add_option("--trace", o->trace, "their trajectory, in the --trace CSV format (scenes/README.md)")->required();
  cmd->add_option("--tolerance", o->tolerance, "position=1e-3,angle=1e-3,velocity=1e-2 (the defaults)");
  cmd->add_option("--plot", o->plot, "write an error-against-time chart into this directory");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("compare " + o->scene, [&] { return compare(*o); }); });
}

}  // namespace render::cli

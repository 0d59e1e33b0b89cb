// `rigidreel sweep`: every combination of integrators, collision methods, steps and iterations
// on one scene, as a CSV, a log-log work-precision chart (cost against error) and a table.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "render/analysis/chart.h"
#include "render/analysis/sweep.h"
#include "render/cli/commands.h"
#include "render/cli/method_lists.h"
#include "render/cli/output.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/csv_field.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/video/plan_writer.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::analysis;
using namespace sim::world;
using sim::core::CollisionMethod;

namespace {

struct SweepOptions : MethodLists, Verbosity {
  std::string scene, variant, dt, iterations, substeps, outDir = "out";
  int repeat = 3;
  bool stack = false;
};

std::string methodLabel(const SweepCase& m) {
  std::string s =
      std::string(sim::core::integratorName(m.integrator)) + " + " + std::string(sim::core::collisionMethodName(m.collisions));
  if (m.collisions == sim::core::CollisionMethod::Sequential) s += " (" + std::to_string(m.iterations) + " it)";
  if (m.collisions == sim::core::CollisionMethod::SoftStep && m.substeps > 0) s += " (" + std::to_string(m.substeps) + " sub)";
  return s;
}

// "4,8,16" → {4, 8, 16}, or {fallback} when empty; throws UsageError naming the option
std::vector<int> wholeNumbers(const std::string& text, const std::string& option, int fallback) {
  if (text.empty()) return {fallback};
  std::vector<int> out;
  for (const std::string& item : splitList(text)) {
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (*end != '\0' || n < 1 || n > 1000)
      throw UsageError(option + ": expected whole numbers from 1 to 1000, got '" + item + "'");
    out.push_back(static_cast<int>(n));
  }
  if (out.empty()) throw UsageError(option + ": give at least one whole number");
  return out;
}

// --stack: cost per step against how far the stack moved from its rest pose, one line per method
// through its iterations or substeps (the work-precision chart of stack solvers)
int stackSweep(const SweepOptions& o, const sim::scene::SceneDef& def, const std::vector<SweepRow>& rows, const std::string& base,
               AtomicFile& csv) {
  csv.stream()
      << "integrator,collisions,dt,iterations,substeps,steps,cpu_seconds_per_step,top_displacement,max_displacement,fastest\n";
  for (const SweepRow& r : rows)
    csv.stream() << sim::core::integratorName(r.method.integrator) << ',' << sim::core::collisionMethodName(r.method.collisions)
                 << ',' << formatNumber(r.method.dt) << ',' << r.method.iterations << ',' << r.method.substeps << ',' << r.steps
                 << ',' << formatNumber(r.secondsPerStep) << ',' << formatNumber(r.topDisplacement) << ','
                 << formatNumber(r.maxDisplacement) << ',' << formatNumber(r.fastest) << '\n';
  Chart chart;
  chart.title = def.name + ": cost against the top body's displacement from rest after " + formatNumber(def.duration) + " s";
  chart.xLabel = "cost: processor milliseconds per step (median of " + std::to_string(o.repeat) + " runs)";
  chart.yLabel = "top body's displacement from rest, m";
  chart.logX = chart.logY = true;
  std::map<std::string, ChartSeries> byMethod;
  std::vector<std::string> order;
  for (const SweepRow& r : rows) {
    // one line per method (and integrator, and step): its points are its iterations or substeps
    std::string label = std::string(sim::core::collisionMethodName(r.method.collisions));
    if (o.integratorList().size() > 1) label += " + " + std::string(sim::core::integratorName(r.method.integrator));
    if (!o.dt.empty() && parseRange(o.dt, "--dt").size() > 1) label += " dt " + formatNumber(r.method.dt);
    if (!byMethod.count(label)) order.push_back(label), byMethod[label].title = label;
    if (r.finite && r.topDisplacement > 0.0 && r.secondsPerStep > 0.0)
      byMethod[label].points.emplace_back(1e3 * r.secondsPerStep, r.topDisplacement);
  }
  for (const std::string& label : order) chart.series.push_back(byMethod[label]);
  writeChart(chart, base + ".png");
  csv.commit();

  std::cout << std::left << std::setw(40) << "method" << std::right << std::setw(12) << "dt" << std::setw(14) << "ms/step"
            << std::setw(14) << "top m" << std::setw(14) << "farthest m" << std::setw(14) << "fastest m/s" << '\n';
  for (const SweepRow& r : rows)
    std::cout << std::left << std::setw(40) << methodLabel(r.method) << std::right << std::setprecision(4) << std::setw(12)
              << r.method.dt << std::setw(14) << 1e3 * r.secondsPerStep << std::setw(14) << r.topDisplacement << std::setw(14)
              << r.maxDisplacement << std::setw(14) << r.fastest << '\n';
  std::cout << "displacements against: the rest pose (where the bodies start)\nwrote " << base << ".csv and " << base << ".png\n";
  if (o.verbose) printFile(base + ".csv");
  return kExitOk;
}

int sweep(const SweepOptions& o) {
  SceneOptions so;
  so.scene = o.scene;
  so.variant = o.variant;
  const SilencedOutput silenced(o.quiet);
  if (so.is3d()) return sweep3d(so, o, o.dt, o.repeat, o.outDir, o.verbose);
  const sim::scene::SceneDef def = so.load().model();
  startWorld(def, o.scene);  // bad start states are reported before the long run

  const auto integrators = o.integratorList();
  const auto methods = o.collisionList({def.collisions});
  const std::vector<double> steps = o.dt.empty() ? defaultSweepSteps(def.dt) : parseRange(o.dt, "--dt");
  const std::vector<int> iterations = wholeNumbers(o.iterations, "--iterations", def.velocityIterations);
  const std::vector<int> substeps = wholeNumbers(o.substeps, "--substeps", def.substeps);
  if (o.repeat < 1 || o.repeat > 1000) throw UsageError("--repeat: expected a whole number from 1 to 1000");
  render::video::createOutputDirectory(o.outDir);

  const double smallest = *std::min_element(steps.begin(), steps.end());
  // (a reference run unless an entry gives values: energy_never_rises gives none)
  const bool values = std::any_of(def.expects.begin(), def.expects.end(), [](const auto& e) { return !e.energyNeverRises; });
  checkSweepSteps(smallest, !o.stack && !values, def.maxSteps, def.duration);
  // the CSV's temporary opened before the runs: a folder that cannot be written fails now
  const std::string base = o.outDir + "/" + def.name + (def.variant.empty() ? "" : "-" + def.variant) + "-sweep";
  AtomicFile csv = openOutput(base + ".csv");
  // a stack is measured against where it stands at the start, a motion against a finer run
  const SweepReference reference = o.stack ? SweepReference{kRestPose, {}} : sweepReference(def, smallest);
  std::vector<SweepRow> rows;
  using sim::core::CollisionMethod;
  for (CollisionMethod c : methods)
    for (sim::core::Integrator i : integrators)
      for (int it : c == CollisionMethod::Sequential ? iterations : std::vector<int>{def.velocityIterations})
        for (int sub : c == CollisionMethod::SoftStep && (o.stack || !o.substeps.empty()) ? substeps : std::vector<int>{0})
          for (double h : steps) rows.push_back(runSweepCase(def, {i, c, h, it, sub}, reference, o.repeat));

  if (o.stack) return stackSweep(o, def, rows, base, csv);
  // the CSV: the columns the issue names, then what the error was measured against
  csv.stream()
      << "integrator,collisions,dt,iterations,steps,seconds_per_sim_second,error,energy_drift,max_penetration,reference\n";
  for (const SweepRow& r : rows)
    csv.stream() << sim::core::integratorName(r.method.integrator) << ',' << sim::core::collisionMethodName(r.method.collisions)
                 << ',' << formatNumber(r.method.dt) << ',' << r.method.iterations << ',' << r.steps << ','
                 << formatNumber(r.secondsPerSimSecond) << ',' << formatNumber(r.error) << ',' << formatNumber(r.energyDrift)
                 << ',' << formatNumber(r.maxPenetration) << ',' << csvField(reference.name) << '\n';

  // the chart: cost on x, error on y, one line per method
  Chart chart;
  chart.title = def.name + ": work against precision (error vs " + reference.name + ")";
  chart.xLabel = "cost: wall seconds per simulated second";
  chart.yLabel = "error";
  chart.logX = chart.logY = true;
  std::map<std::string, ChartSeries> byMethod;
  std::vector<std::string> order;
  for (const SweepRow& r : rows) {
    const std::string label = methodLabel(r.method);
    if (!byMethod.count(label)) order.push_back(label), byMethod[label].title = label;
    if (r.finite && r.error > 0.0 && r.secondsPerSimSecond > 0.0)
      byMethod[label].points.emplace_back(r.secondsPerSimSecond, r.error);
  }
  // each line joins a method's runs in the order of their steps
  for (const std::string& label : order) chart.series.push_back(byMethod[label]);
  if (std::all_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.error == 0.0; })) chart.note = kAllErrorsZero;
  writeChart(chart, base + ".png");
  csv.commit();

  std::cout << std::left << std::setw(40) << "method" << std::right << std::setw(12) << "dt" << std::setw(10) << "steps"
            << std::setw(14) << "s/sim s" << std::setw(14) << "error" << std::setw(14) << "energy drift" << std::setw(14)
            << "penetration" << '\n';
  for (const SweepRow& r : rows)
    std::cout << std::left << std::setw(40) << methodLabel(r.method) << std::right << std::setprecision(4) << std::setw(12)
              << r.method.dt << std::setw(10) << r.steps << std::setw(14) << r.secondsPerSimSecond << std::setw(14) << r.error
              << std::setw(14) << r.energyDrift << std::setw(14) << r.maxPenetration << '\n';
  std::cout << "error against: " << reference.name << "\nwrote " << base << ".csv and " << base << ".png\n";
  if (o.verbose) printFile(base + ".csv");
  return kExitOk;
}

}  // namespace

void addSweepCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "run a scene under many methods and steps: cost against error");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  cmd->add_option("--variant", o->variant, "the named variant of the scene");
  o->MethodLists::addTo(*cmd);
  cmd->add_option("--dt", o->dt, "FROM:TO:COUNT, log-spaced steps (default: 8·dt to dt/8, 7 steps)");
  cmd->add_option("--iterations", o->iterations, "comma-separated velocity iterations for sequential");
  cmd->add_option("--substeps", o->substeps, "comma-separated substeps for soft_step");
  cmd->add_flag("--stack", o->stack,
                "measure a stack: cost per step against the top body's displacement from its rest pose (and the "
                "farthest and fastest body), one line per method through its iterations or substeps");
  cmd->add_option("--repeat", o->repeat, "timed runs per case; the median is kept (default 3)");
  cmd->add_option("-o,--output", o->outDir, "output directory (default out)");
  o->Verbosity::addTo(*cmd, "print nothing (the CSV and the chart are still written); errors still on standard error",
                      "also the CSV's rows, every column in full, after the table");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("sweep " + o->scene, [&] { return sweep(*o); }); });
}

}  // namespace render::cli

// `rigidreel sweep` and `rigidreel stability` of a 3D scene: the integrators (the splitting among
// them) against cost and error, with the energy and |L| drift and | |q| − 1 | the 2D CSVs do not
// have; and the largest step at which each holds the scene.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "render/analysis/analysis3d.h"
#include "render/analysis/chart.h"
#include "render/analysis/sweep.h"
#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/space3d.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/csv_field.h"
#include "render/jobs/json_writer.h"
#include "render/video/plan_writer.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::analysis;
using namespace sim::core;
using sim::world3d::Integrator;
using sim::world3d::kIntegratorNames;

namespace {

// the named integrators, or all five
std::vector<Integrator> integrators3d(const MethodLists& m) {
  if (!m.collisions.empty()) throw UsageError("--collisions: 3D scenes have no contacts, so no collision method to choose");
  std::vector<Integrator> out;
  for (const auto& e : kIntegratorNames.entries()) out.push_back(e.value);
  if (m.integrators.empty()) return out;
  out.clear();
  for (const std::string& item : splitList(m.integrators)) {
    const auto value = kIntegratorNames.parse(item);
    if (!value) throw UsageError("--integrators: unknown name '" + item + "'; choose from: " + kIntegratorNames.list());
    out.push_back(*value);
  }
  if (out.empty()) throw UsageError("--integrators: give at least one name");
  return out;
}

// the start of the outputs' names: DIR/<scene>[-<variant>]-<what>
std::string analysisBase(const std::string& outDir, const sim::scene3d::SceneDef& def, const std::string& what) {
  return outDir + "/" + def.name + (def.variant.empty() ? "" : "-" + def.variant) + "-" + what;
}

}  // namespace

int sweep3d(const SceneOptions& so, const MethodLists& methods, const std::string& dt, int repeat, const std::string& outDir,
            bool verbose) {
  const sim::scene3d::SceneDef def = so.load3d().model();
  const std::vector<Integrator> integrators = integrators3d(methods);
  const std::vector<double> steps = dt.empty() ? defaultSweepSteps(def.dt) : parseRange(dt, "--dt");
  if (repeat < 1 || repeat > 1000) throw UsageError("--repeat: expected a whole number from 1 to 1000");
  render::video::createOutputDirectory(outDir);
  checkSweepSteps(*std::min_element(steps.begin(), steps.end()), def.expects.empty(), def.maxSteps, def.duration);
  // the CSV's temporary opened before the runs: a folder that cannot be written fails now
  const std::string base = analysisBase(outDir, def, "sweep");
  AtomicFile csv = openOutput(base + ".csv");

  const Sweep3dReference reference = sweepReference3d(def, *std::min_element(steps.begin(), steps.end()));
  std::vector<Sweep3dRow> rows;
  for (Integrator i : integrators)
    for (double h : steps) rows.push_back(runSweepCase3d(def, i, h, reference, repeat));

  // the 2D sweep's columns (no collisions, iterations or penetration in 3D), then |L| and |q| drift
  csv.stream() << "integrator,collisions,dt,iterations,steps,seconds_per_sim_second,error,energy_drift,max_penetration,"
                  "angular_momentum_drift,quaternion_drift,reference\n";
  Chart chart;
  chart.title = def.name + ": work against precision (error vs " + reference.name + ")";
  chart.xLabel = "cost: wall seconds per simulated second";
  chart.yLabel = "error";
  chart.logX = chart.logY = true;
  for (Integrator i : integrators) chart.series.push_back({std::string(kIntegratorNames.name(i)), {}});
  for (const Sweep3dRow& r : rows) {
    const RunMetrics& m = r.metrics;
    csv.stream() << kIntegratorNames.name(r.integrator) << ",none," << formatNumber(r.dt) << ",0," << r.steps << ','
                 << formatNumber(r.secondsPerSimSecond) << ',' << formatNumber(r.error) << ',' << formatNumber(m.energyDrift)
                 << ",0," << formatNumber(m.angularMomentumDrift) << ',' << formatNumber(m.quaternionDrift) << ','
                 << csvField(reference.name) << '\n';
    const size_t series = std::find(integrators.begin(), integrators.end(), r.integrator) - integrators.begin();
    if (m.finite && r.error > 0.0 && r.secondsPerSimSecond > 0.0)
      chart.series[series].points.emplace_back(r.secondsPerSimSecond, r.error);
  }
  if (std::all_of(rows.begin(), rows.end(), [](const Sweep3dRow& r) { return r.error == 0.0; })) chart.note = kAllErrorsZero;
  writeChart(chart, base + ".png");
  csv.commit();

  std::cout << std::left << std::setw(18) << "integrator" << std::right << std::setw(12) << "dt" << std::setw(10) << "steps"
            << std::setw(14) << "s/sim s" << std::setw(14) << "error" << std::setw(14) << "energy drift" << std::setw(14)
            << "|L| drift" << std::setw(14) << "||q| - 1|" << '\n';
  for (const Sweep3dRow& r : rows)
    std::cout << std::left << std::setw(18) << kIntegratorNames.name(r.integrator) << std::right << std::setprecision(4)
              << std::setw(12) << r.dt << std::setw(10) << r.steps << std::setw(14) << r.secondsPerSimSecond << std::setw(14)
              << r.error << std::setw(14) << r.metrics.energyDrift << std::setw(14) << r.metrics.angularMomentumDrift
              << std::setw(14) << r.metrics.quaternionDrift << '\n';
  std::cout << "error against: " << reference.name << "\nwrote " << base << ".csv and " << base << ".png\n";
  if (verbose) printFile(base + ".csv");
  return kExitOk;
}

int stability3d(const SceneOptions& so, const MethodLists& methods, const std::string& outDir, bool verbose) {
  const SceneFile3d file = so.load3d();
  const sim::scene3d::SceneDef& def = file.model();
  const std::vector<Integrator> integrators = integrators3d(methods);
  render::video::createOutputDirectory(outDir);
  const std::string base = analysisBase(outDir, def, "stability");
  AtomicFile csv = openOutput(base + ".csv");
  csv.stream() << "integrator,collisions,parameter,largest_stable,first_failing,failure\n";
  Chart chart;
  chart.title = def.name + ": the largest dt at which each method holds";
  chart.yLabel = "largest stable dt";
  chart.bars = chart.logY = true;
  ChartSeries bars{"largest stable dt", {}};
  for (Integrator i : integrators) {
    sim::scene3d::SceneDef d = def;
    d.integrator = i;
    const StabilityResult r = findBoundary3d(d, file.stability);
    const std::string name(kIntegratorNames.name(i));
    std::cout << describeBoundary(name, "dt", r) << '\n';
    csv.stream() << name << ",none,dt," << formatNumber(r.largestStable) << ',' << formatNumber(r.firstFailing) << ','
                 << csvField(r.holdsToLimit ? "none" : r.failing.failure) << '\n';
    chart.barLabels.push_back(name);
    bars.points.emplace_back(static_cast<double>(bars.points.size()), r.largestStable > 0.0 ? r.largestStable : NAN);
  }
  chart.series.push_back(bars);
  writeChart(chart, base + ".png");
  csv.commit();
  std::cout << "wrote " << base << ".csv and " << base << ".png\n";
  if (verbose) printFile(base + ".csv");
  return kExitOk;
}

}  // namespace render::cli

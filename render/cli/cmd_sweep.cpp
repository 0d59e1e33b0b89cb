// `rigidreel sweep`: every combination of integrators, collision methods, steps and iterations
// on one scene, as a CSV, a log-log work-precision chart (cost against error) and a table.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "render/analysis/chart.h"
#include "render/analysis/sweep.h"
#include "render/cli/commands.h"
#include "render/cli/method_lists.h"
#include "render/cli/scene_options.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/json_writer.h"

namespace render::cli {
using namespace render::jobs;
using namespace render::analysis;

namespace {

struct SweepOptions : MethodLists {
  std::string scene, variant, dt, iterations, outDir = "out";
  int repeat = 3;
};

std::string methodLabel(const SweepCase& m) {
  std::string s = std::string(sim::core::integratorName(m.integrator)) + " + " + std::string(sim::world::collisionMethodName(m.collisions));
  if (m.collisions == sim::world::CollisionMethod::Sequential) s += " (" + std::to_string(m.iterations) + " it)";
  return s;
}

int sweep(const SweepOptions& o) {
  SceneOptions so;
  so.scene = o.scene;
  so.variant = o.variant;
  const sim::scene::SceneDef def = so.load().model();
  startWorld(def, o.scene);  // bad start states are reported before the long run

  const auto integrators = o.integratorList();
  const auto methods = o.collisionList({def.collisions});
  const std::vector<double> steps =
      o.dt.empty() ? parseRange(std::to_string(def.dt * 8) + ":" + std::to_string(def.dt / 8) + ":7", "--dt")
                   : parseRange(o.dt, "--dt");
  std::vector<int> iterations{def.velocityIterations};
  if (!o.iterations.empty()) {
    iterations.clear();
    for (const std::string& item : splitList(o.iterations)) {
      char* end = nullptr;
      const long n = std::strtol(item.c_str(), &end, 10);
      if (*end != '\0' || n < 1 || n > 1000) throw UsageError("--iterations: expected whole numbers from 1 to 1000, got '" + item + "'");
      iterations.push_back(static_cast<int>(n));
    }
  }
  if (o.repeat < 1 || o.repeat > 1000) throw UsageError("--repeat: expected a whole number from 1 to 1000");
  std::filesystem::create_directories(o.outDir);

  const double smallest = *std::min_element(steps.begin(), steps.end());
  const SweepReference reference = sweepReference(def, smallest);
  std::vector<SweepRow> rows;
  for (sim::world::CollisionMethod c : methods)
    for (sim::core::Integrator i : integrators)
      for (int it : c == sim::world::CollisionMethod::Sequential ? iterations : std::vector<int>{def.velocityIterations})
        for (double h : steps) rows.push_back(runSweepCase(def, {i, c, h, it}, reference, o.repeat));

  // the CSV: the columns the issue names, then what the error was measured against
  const std::string base = o.outDir + "/" + def.name + (def.variant.empty() ? "" : "-" + def.variant) + "-sweep";
  AtomicFile csv(base + ".csv");
  csv.stream() << "integrator,collisions,dt,iterations,steps,seconds_per_sim_second,error,energy_drift,max_penetration,reference\n";
  for (const SweepRow& r : rows)
    csv.stream() << sim::core::integratorName(r.method.integrator) << ',' << sim::world::collisionMethodName(r.method.collisions) << ','
                 << formatNumber(r.method.dt) << ',' << r.method.iterations << ',' << r.steps << ','
                 << formatNumber(r.secondsPerSimSecond) << ',' << formatNumber(r.error) << ','
                 << formatNumber(r.energyDrift) << ',' << formatNumber(r.maxPenetration) << ',' << reference.name << '\n';

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
  writeChart(chart, base + ".png");
  csv.commit();

  std::cout << std::left << std::setw(40) << "method" << std::right << std::setw(12) << "dt" << std::setw(10) << "steps"
            << std::setw(14) << "s/sim s" << std::setw(14) << "error" << std::setw(14) << "energy drift" << std::setw(14)
            << "penetration" << '\n';
  for (const SweepRow& r : rows)
    std::cout << std::left << std::setw(40) << methodLabel(r.method) << std::right << std::setprecision(4) << std::setw(12)
              << r.method.dt << std::setw(10) << r.steps << std::setw(14) << r.secondsPerSimSecond << std::setw(14)
              << r.error << std::setw(14) << r.energyDrift << std::setw(14) << r.maxPenetration << '\n';
  std::cout << "error against: " << reference.name << "\nwrote " << base << ".csv and " << base << ".png\n";
  return kExitOk;
}

}  // namespace

void addSweepCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "run a scene under many methods and steps: cost against error");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  cmd->add_option("--variant", o->variant, "the named variant of the scene");
  o->addTo(*cmd);
  cmd->add_option("--dt", o->dt, "FROM:TO:COUNT, log-spaced steps (default: 8·dt to dt/8, 7 steps)");
  cmd->add_option("--iterations", o->iterations, "comma-separated velocity iterations for sequential");
  cmd->add_option("--repeat", o->repeat, "timed runs per case; the median is kept (default 3)");
  cmd->add_option("-o", o->outDir, "output directory (default out)");
  cmd->callback([o, &exitCode] { exitCode = sweep(*o); });
}

}  // namespace render::cli

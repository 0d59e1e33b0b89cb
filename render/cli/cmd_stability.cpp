// `rigidreel stability`: for each method, the largest step (or speed, mass ratio, stack height, as
// the scene's `stability:` block declares) at which the scene still holds, and how it fails beyond.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "render/analysis/chart.h"
#include "render/analysis/stability.h"
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
using namespace sim::collision;
using sim::core::CollisionMethod;

namespace {

struct StabilityOptions : MethodLists, Verbosity {
  std::string scene, variant, outDir = "out";
};

// the collision methods to compare without --collisions: those the scene's variants choose, so that
// a scene whose variants are the methods compares them all; without variants (or with --variant) the
// scene's own, and for a scene whose bodies can meet every method that makes them collide (`auto`
// alone where no two bodies can meet: the others would repeat its numbers)
std::vector<sim::core::CollisionMethod> defaultCollisions(const StabilityOptions& o, const OpenScene& file,
                                                          const sim::scene::SceneDef& def) {
  using sim::core::CollisionMethod;
  std::vector<CollisionMethod> methods;
  if (o.variant.empty() && !def.variantNames.empty()) {
    for (const std::string& v : def.variantNames) {
      const CollisionMethod m = file.read(v).model().collisions;
      if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
    }
    return methods;
  }
  if (!o.variant.empty() || startWorld(def, o.scene).collisions() == CollisionMethod::None) return {def.collisions};
  return {CollisionMethod::Event, CollisionMethod::Isolated, CollisionMethod::Sequential};
}

int stability(const StabilityOptions& o) {
  SceneOptions so;
  so.scene = o.scene;
  so.variant = o.variant;
  const SilencedOutput silenced(o.quiet);
  if (so.is3d()) return stability3d(so, o, o.outDir, o.verbose);
  const render::analysis::Study study = so.load().study();
  const sim::scene::SceneDef& def = study.model;
  startWorld(def, o.scene);

  const auto integrators = o.integratorList();
  const auto methods = o.collisionList(defaultCollisions(o, so.open(), def));
  render::video::createOutputDirectory(o.outDir);
  const std::string base = o.outDir + "/" + def.name + (def.variant.empty() ? "" : "-" + def.variant) + "-stability";
  const std::string parameter(kParameterNames.name(study.stability.parameter));

  AtomicFile csv = openOutput(base + ".csv");
  // for iterations and substeps the search finds the fewest that hold: the columns say so
  const bool fewest = study.stability.fewest();
  csv.stream() << (fewest ? "integrator,collisions,parameter,fewest_holding,most_failing,failure\n"
                          : "integrator,collisions,parameter,largest_stable,first_failing,failure\n");
  Chart chart;
  chart.title = def.name + (fewest ? ": the fewest " : ": the largest ") + parameter + " at which each method holds";
  chart.yLabel = (fewest ? std::string("fewest ") : std::string("largest stable ")) + parameter;
  chart.bars = true;
  chart.barValues = true;
  chart.logY = !study.stability.countsBodies();
  // a method that held up to the search's limit has no boundary found: its bar is a lower bound;
  // for the fewest iterations, a method that failed up to the limit needs more than its bar
  ChartSeries bars{chart.yLabel, {}};
  ChartSeries bounds{
      fewest ? "fails up to the search's limit (needs more)" : "holds up to the search's limit (at least this)", {}, true};
  for (sim::core::CollisionMethod c : methods)
    for (sim::core::Integrator i : integrators) {
      Study d = study;
      d.model.integrator = i;
      d.model.collisions = c;
      const StabilityResult r = findBoundary(d);
      std::cout << describeFailure(d, r) << '\n';
      const bool open = fewest ? r.failsEverywhere : r.holdsToLimit;
      csv.stream() << sim::core::integratorName(i) << ',' << sim::core::collisionMethodName(c) << ',' << parameter << ','
                   << formatNumber(r.largestStable) << ',' << formatNumber(r.firstFailing) << ','
                   << csvField(r.holdsToLimit ? "none" : r.failing.failure) << '\n';
      const double x = static_cast<double>(chart.barLabels.size());
      chart.barLabels.push_back(std::string(sim::core::integratorName(i)) + "\n" +
                                std::string(sim::core::collisionMethodName(c)));
      const double value = fewest && r.failsEverywhere ? r.firstFailing : r.largestStable;
      (open ? bounds : bars).points.emplace_back(x, value > 0.0 ? value : NAN);
    }
  // when every method fails at every value tried there is nothing to draw on a log axis: draw the
  // zeros on a linear one (gnuplot refuses a chart without a valid point)
  const auto drawn = [](const ChartSeries& s) {
    return std::any_of(s.points.begin(), s.points.end(), [](const auto& p) { return std::isfinite(p.second); });
  };
  if (!drawn(bars) && !drawn(bounds)) {
    chart.logY = false;
    for (auto& p : bars.points) p.second = 0.0;
  }
  chart.series.push_back(bars);
  if (!bounds.points.empty()) chart.series.push_back(bounds);
  writeChart(chart, base + ".png");
  csv.commit();
  std::cout << "wrote " << base << ".csv and " << base << ".png\n";
  if (o.verbose) printFile(base + ".csv");
  return kExitOk;
}

}  // namespace

void addStabilityCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand("stability", "find where each method stops holding a scene");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  cmd->add_option("--variant", o->variant, "the named variant of the scene");
  o->MethodLists::addTo(*cmd);
  cmd->add_option("-o,--output", o->outDir, "output directory (default out)");
  o->Verbosity::addTo(*cmd, "print nothing (the CSV and the chart are still written); errors still on standard error",
                      "also the CSV's rows, every column in full, after the lines");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("stability " + o->scene, [&] { return stability(*o); }); });
}

}  // namespace render::cli

// `rigidreel stability`: for each method, the largest step (or speed, mass ratio, stack height, as
// the scene's `stability:` block declares) at which the scene still holds, and how it fails beyond.
#include <filesystem>
#include <iostream>

#include "atomic_file.h"
#include "chart.h"
#include "commands.h"
#include "json_writer.h"
#include "method_lists.h"
#include "scene_options.h"
#include "stability.h"

namespace render {

namespace {

struct StabilityOptions : MethodLists {
  std::string scene, variant, outDir = "out";
};

int stability(const StabilityOptions& o) {
  SceneOptions so;
  so.scene = o.scene;
  so.variant = o.variant;
  const sim::SceneDef def = so.load();
  startWorld(def, o.scene);

  const auto integrators = o.integratorList();
  const auto methods = o.collisionList(def.collisions);
  std::filesystem::create_directories(o.outDir);
  const std::string base = o.outDir + "/" + def.name + (def.variant.empty() ? "" : "-" + def.variant) + "-stability";
  const char* parameter = parameterName(def.stability.parameter);

  AtomicFile csv(base + ".csv");
  csv.stream() << "integrator,collisions,parameter,largest_stable,first_failing,failure\n";
  Chart chart;
  chart.title = def.name + ": the largest " + parameter + " at which each method holds";
  chart.yLabel = std::string("largest stable ") + parameter;
  chart.bars = true;
  chart.logY = def.stability.parameter != sim::StabilityDef::Parameter::StackHeight;
  ChartSeries bars{std::string("largest stable ") + parameter, {}};
  for (sim::CollisionMethod c : methods)
    for (sim::Integrator i : integrators) {
      sim::SceneDef d = def;
      d.integrator = i;
      d.collisions = c;
      const StabilityResult r = findBoundary(d);
      std::cout << describeFailure(d, r) << '\n';
      csv.stream() << sim::integratorName(i) << ',' << sim::collisionMethodName(c) << ',' << parameter << ','
                   << formatNumber(r.largestStable) << ',' << formatNumber(r.firstFailing) << ','
                   << (r.holdsToLimit ? "none" : r.failing.failure) << '\n';
      chart.barLabels.push_back(std::string(sim::integratorName(i)) + "\\n" + std::string(sim::collisionMethodName(c)));
      bars.points.emplace_back(static_cast<double>(bars.points.size()), r.largestStable > 0.0 ? r.largestStable : NAN);
    }
  chart.series.push_back(bars);
  writeChart(chart, base + ".png");
  csv.commit();
  std::cout << "wrote " << base << ".csv and " << base << ".png\n";
  return kExitOk;
}

}  // namespace

void addStabilityCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand("stability", "find where each method stops holding a scene");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  cmd->add_option("--variant", o->variant, "the named variant of the scene");
  o->addTo(*cmd);
  cmd->add_option("-o", o->outDir, "output directory (default out)");
  cmd->callback([o, &exitCode] { exitCode = stability(*o); });
}

}  // namespace render

// `rigidreel expect`: `expect` entries from a run, ready to paste into the scene: the position,
// angle and velocity (with ω) of each moving body at each time, the values as `check` will see them.
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "render/analysis/interrupt_check.h"
#include "render/cli/commands.h"
#include "render/cli/decimal_text.h"
#include "render/cli/scene_options.h"
#include "render/cli/yaml_scalar.h"
#include "render/jobs/json_writer.h"
#include "sim/scene/expect.h"

namespace render::cli {
using namespace render::jobs;

namespace {

struct ExpectCommand : SceneOptions {
  std::string at;
  double tolerance = 1e-9;
};

// "0.5,1" → {0.5, 1}, each within [0, duration]; throws UsageError
std::vector<double> times(const std::string& text, double duration) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const double t = decimalText(item).value_or(-1.0);
    if (!(t >= 0.0 && t <= duration))
      throw UsageError("--at: expected times in seconds within [0, " + formatNumber(duration) + "] separated by commas, got '" +
                       item + "'");
    out.push_back(t);
  }
  if (out.empty()) throw UsageError("--at: give at least one time");
  return out;
}

std::string pair(const std::vector<double>& v) { return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + "]"; }

int expect(const ExpectCommand& o) {
  if (o.is3d()) throw UsageError(o.scene + ": a 3D scene; expect takes 2D scenes for now");
  if (!(o.tolerance >= 0.0) || !std::isfinite(o.tolerance))
    throw UsageError("--tolerance: give zero or a positive finite number, got " + formatNumber(o.tolerance));
  sim::scene::SceneDef def = o.load().model();
  const std::vector<double> at = o.at.empty() ? std::vector<double>{def.duration} : times(o.at, def.duration);
  // measured as `check` will run the scene with them pasted in: the scene's own entries stay, since
  // the run stops at each entry's time
  const size_t own = def.expects.size();
  for (double t : at)
    for (const sim::scene::BodyDef& b : def.bodies)
      if (!b.isStatic) {
        sim::scene::ExpectDef e;
        e.time = t;
        e.body = b.name;
        e.position = sim::core::Vec2::Zero();
        e.angle = 0.0;
        e.velocity = sim::core::Vec2::Zero();
        e.angularVelocity = 0.0;
        def.expects.push_back(e);
      }
  sim::world::World world = startWorld(def, o.scene);
  render::analysis::InterruptCheck interrupt;
  const std::vector<sim::core::CheckResult> results = sim::scene::runExpects(def, world, &interrupt);
  std::cout << "# rigidreel expect " << o.scene << (def.variant.empty() ? "" : " --variant " + def.variant) << '\n';
  std::cout << "expect:\n";
  for (size_t i = own; i < def.expects.size(); ++i) {
    const sim::scene::ExpectDef& e = def.expects[i];
    const auto find = [&](const std::string& quantity) -> const sim::core::CheckResult& {
      // (an entry of the scene's own at the same time and body measured the same state)
      for (const sim::core::CheckResult& r : results)
        if (r.time == e.time && r.quantity == quantity) return r;
      throw std::logic_error("no result for " + quantity);
    };
    std::cout << "  - {time: " << formatNumber(e.time) << ", body: " << yamlScalar(e.body)
              << ", position: " << pair(find(e.body + ".position").actual)
              << ", angle: " << formatNumber(find(e.body + ".angle").actual[0])
              << ", velocity: " << pair(find(e.body + ".velocity").actual)
              << ", angular_velocity: " << formatNumber(find(e.body + ".angular_velocity").actual[0])
              << ", tolerance: " << formatNumber(o.tolerance) << "}\n";
  }
  return kExitOk;
}

}  // namespace

void addExpectCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ExpectCommand>();
  CLI::App* cmd = app.add_subcommand("expect", "print expect entries (YAML) of each moving body's state from a run");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->addTo(*cmd);
  cmd->add_option("--at", o->at, "times in seconds, separated by commas (default: the scene's duration)");
  cmd->add_option("--tolerance", o->tolerance, "each entry's tolerance (default: 1e-9)");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("expect " + o->scene, [&] { return expect(*o); }); });
}

}  // namespace render::cli

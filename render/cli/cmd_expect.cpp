// `rigidreel expect`: `expect` entries from a run, ready to paste into the scene: the position,
// angle (in 3D the orientation) and velocity (with ω) of each moving body at each time, the values
// as `check` will see them, each marked `source: earlier_run`.
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

#include "render/analysis/interrupt_check.h"
#include "render/cli/commands.h"
#include "render/cli/decimal_text.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/cli/yaml_scalar.h"
#include "render/jobs/json_writer.h"
#include "sim/scene/expect.h"
#include "sim/scene3d/expect.h"

namespace render::cli {
using namespace render::jobs;

namespace {

struct ExpectCommand : SceneOptions, Verbosity {
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

// "0.5" for one value, "[1, 2, 3]" for a vector
std::string shown(const std::vector<double>& v) {
  if (v.size() == 1) return formatNumber(v[0]);
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatNumber(v[i]);
  return s + "]";
}

// the entries of a 2D or a 3D scene: `state(t, body)` an entry asking for a body's whole state, its
// `keys` the quantities it compares, `run` the run `check` makes of the scene (its world started
// there), which says in `how` its integrator, step and collision method for -v
template <class Def, class Entry>
int printEntries(const ExpectCommand& o, Def def, const std::vector<std::string>& keys,
                 const std::function<Entry(double, const std::string&)>& state,
                 const std::function<std::vector<sim::core::CheckResult>(Def&, std::string& how)>& run) {
  if (!(o.tolerance >= 0.0) || !std::isfinite(o.tolerance))
    throw UsageError("--tolerance: give zero or a positive finite number, got " + formatNumber(o.tolerance));
  const std::vector<double> at = o.at.empty() ? std::vector<double>{def.duration} : times(o.at, def.duration);
  // measured as `check` will run the scene with them pasted in: the scene's own entries stay, since
  // the run stops at each entry's time
  const size_t own = def.expects.size();
  for (double t : at)
    for (const auto& b : def.bodies)
      if (!isStaticBody(b)) def.expects.push_back(state(t, b.name));
  std::string how;
  const std::vector<sim::core::CheckResult> results = run(def, how);
  // --quiet: the entries alone, to append under a scene's own expect:; -v: also how they were measured
  if (!o.quiet) std::cout << "# rigidreel expect " << o.scene << (def.variant.empty() ? "" : " --variant " + def.variant) << '\n';
  if (o.verbose) std::cout << "# measured as check runs the scene: " << how << '\n';
  if (!o.quiet) std::cout << "expect:\n";
  for (size_t i = own; i < def.expects.size(); ++i) {
    const Entry& e = def.expects[i];
    const auto find = [&](const std::string& quantity) -> const sim::core::CheckResult& {
      // (an entry of the scene's own at the same time and body measured the same state)
      for (const sim::core::CheckResult& r : results)
        if (r.time == e.time && r.quantity == quantity) return r;
      throw std::logic_error("no result for " + quantity);
    };
    std::cout << "  - {time: " << formatNumber(e.time) << ", body: " << yamlScalar(e.body);
    for (const std::string& key : keys) std::cout << ", " << key << ": " << shown(find(e.body + "." + key).actual);
    // a run's values, not closed forms: the lecture page lists them apart
    std::cout << ", tolerance: " << formatNumber(o.tolerance) << ", source: earlier_run}\n";
  }
  return kExitOk;
}

int expect2d(const ExpectCommand& o) {
  using sim::scene::ExpectDef;
  using sim::scene::SceneDef;
  return printEntries<SceneDef, ExpectDef>(
      o, o.load().model(), {"position", "angle", "velocity", "angular_velocity"},
      [](double t, const std::string& body) {
        ExpectDef e;
        e.time = t, e.body = body;
        e.position = sim::core::Vec2::Zero(), e.angle = 0.0, e.velocity = sim::core::Vec2::Zero(), e.angularVelocity = 0.0;
        return e;
      },
      [&](SceneDef& def, std::string& how) {
        sim::world::World world = startWorld(def, o.scene);
        how = "integrator " + std::string(sim::core::integratorName(def.integrator)) + ", dt " + formatNumber(def.dt) +
              " s, collisions " + describeCollisionMethod(def, world);
        render::analysis::InterruptCheck interrupt;
        return sim::scene::runExpects(def, world, &interrupt);
      });
}

int expect3d(const ExpectCommand& o) {
  using sim::scene3d::ExpectDef;
  using sim::scene3d::SceneDef;
  using sim::world3d::Vec3;
  return printEntries<SceneDef, ExpectDef>(
      o, o.load3d().model(), {"position", "orientation", "velocity", "angular_velocity"},
      [](double t, const std::string& body) {
        ExpectDef e;
        e.time = t, e.body = body;
        e.position = Vec3::Zero(), e.orientation = sim::world3d::Quat::Identity(), e.velocity = Vec3::Zero();
        e.angularVelocity = Vec3::Zero();
        return e;
      },
      [&](SceneDef& def, std::string& how) {
        sim::world3d::World world = startWorld3d(def, o.scene);
        how = "integrator " + std::string(sim::world3d::kIntegratorNames.name(def.integrator)) + ", dt " + formatNumber(def.dt) +
              " s, collisions " + describeCollisionMethod(def, world);
        render::analysis::InterruptCheck3d interrupt;
        return sim::scene3d::runExpects(def, world, &interrupt);
      });
}

int expect(const ExpectCommand& o) { return o.is3d() ? expect3d(o) : expect2d(o); }

}  // namespace

void addExpectCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ExpectCommand>();
  CLI::App* cmd = app.add_subcommand("expect", "print expect entries (YAML) of each moving body's state from a run");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->SceneOptions::addTo(*cmd);
  o->Verbosity::addTo(*cmd, "the entries alone, without the comment and the 'expect:' line, to append under a scene's own",
                      "also a comment saying how they were measured: the integrator, dt and collision method");
  cmd->add_option("--at", o->at, "times in seconds, separated by commas (default: the scene's duration)");
  cmd->add_option("--tolerance", o->tolerance, "each entry's tolerance (default: 1e-9)");
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("expect " + o->scene, [&] { return expect(*o); }); });
}

}  // namespace render::cli

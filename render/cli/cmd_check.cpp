// `rigidreel check`: load and validate scenes, say what model each uses, and compare every
// variant's `expect` entries with the simulation.
#include <iostream>
#include <sstream>

#include "render/cli/commands.h"
#include "render/cli/run_progress.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "sim/scene/expect.h"
#include "sim/scene/scene_build.h"
#include "sim/scene3d/expect.h"
#include "sim/scene3d/scene_build.h"
#include "sim/yaml/scene_yaml.h"

namespace render::cli {
using namespace render::jobs;

namespace {

std::string plural(size_t n, const std::string& word) {
  if (n == 1) return "1 " + word;
  return std::to_string(n) + " " + (word.ends_with("y") ? word.substr(0, word.size() - 1) + "ies" : word + "s");
}

// " gravity, 2 springs, drag" or " none": the forces of a 2D or a 3D scene's definitions
template <class Def>
std::string forcesOf(const Def& d, bool gravity) {
  std::string forces;
  if (gravity) forces += " gravity,";
  if (!d.springs.empty()) forces += " " + plural(d.springs.size(), "spring") + ",";
  if (!d.pointForces.empty()) forces += " " + plural(d.pointForces.size(), "point force") + ",";
  if (!d.drags.empty()) forces += " " + std::string("drag,");
  if (forces.empty()) forces = " none,";
  forces.pop_back();
  return forces;
}

// what the scene makes the simulator model: a scene pays only for what it uses
std::string describeModel(const sim::scene::SceneDef& d) {
  size_t dynamic = 0;
  for (const auto& b : d.bodies) dynamic += !b.isStatic;
  std::ostringstream o;
  o << plural(d.bodies.size(), "body") << " (" << dynamic << " dynamic); forces:"
    << forcesOf(d, d.gravity != sim::core::Vec2::Zero()) << "; " << plural(d.events.size(), "impulse event") << "; integrator " << sim::core::integratorName(d.integrator)
    << ", dt " << formatNumber(d.dt) << " s, duration " << formatNumber(d.duration) << " s";
  return o.str();
}

std::string formatValues(const std::vector<double>& v) {
  if (v.size() == 1) return formatNumber(v[0]);
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatNumber(v[i]);
  return s + ")";
}

// each comparison with its error; false when one failed
bool report(const std::vector<sim::core::CheckResult>& results) {
  bool ok = true;
  for (const sim::core::CheckResult& r : results) {
    ok = ok && r.passed();
    std::cout << (r.passed() ? "  ok    " : "  FAIL  ") << "t = " << formatNumber(r.time) << "  " << r.quantity
              << " = " << formatValues(r.actual) << ", expected " << formatValues(r.expected) << ", error "
              << formatNumber(r.error) << " (tolerance " << formatNumber(r.tolerance) << ")\n";
  }
  return ok;
}

// say where the event method found impacts piling up and made the contact resting
void reportResting(const sim::scene::SceneDef& def, const sim::world::World& w) {
  for (const sim::world::RestingRecord& r : w.resting) std::cout << "  resting: " << describeResting(def, r) << '\n';
}

// say when `auto` went from the event method to the stack solver during the run
void reportSwitch(const sim::world::World& w) {
  if (w.methodSwitchTime)
    std::cout << "  switched: " << describeCollisionMethod(w) << '\n';
}

// the run and its expect entries; false when one fails
bool runCase(const sim::scene::SceneDef& def, sim::world::World& w, RunProgress2& progress) {
  if (def.expects.empty()) {
    // still run it: a scene that diverges is not a good scene
    w.advanceTo(def.duration, progress.observer());
    progress.finish();
    std::cout << "  ran to t = " << formatNumber(def.duration) << " (no expect entries)";
    if (!w.impacts.empty()) std::cout << ", " << w.impacts.size() << " impulses";
    std::cout << '\n';
    reportResting(def, w);
    reportSwitch(w);
    return true;
  }
  const std::vector<sim::core::CheckResult> results = sim::scene::runExpects(def, w, progress.observer());
  progress.finish();
  const bool ok = report(results);
  reportResting(def, w);
  reportSwitch(w);
  return ok;
}

// one scene, one variant ("" for the base); returns false when an expect fails
bool checkCase(const std::string& file, const std::string& variant) {
  const sim::scene::SceneDef def = readSceneFile(file, variant).model();
  const std::string label = file + (variant.empty() ? "" : " [" + variant + "]");
  std::cout << label << ": " << describeModel(def) << '\n';
  sim::world::World w = startWorld(def, file);
  std::cout << "  collisions: " << describeCollisionMethod(w) << '\n';
  RunProgress2 progress(label, def.duration);
  try {
    return runCase(def, w, progress);
  } catch (const sim::world::Diverged& d) {
    // named by the body's name, not its index
    throw std::runtime_error("the simulation diverged at t = " + formatNumber(d.time) + " (body '" + def.bodies[d.body].name +
                             "'); use a smaller dt or another integrator");
  }
}

// what a 3D scene models: free bodies, their forces and events, the integrator and whether q is
// normalized after each step
std::string describeModel3(const sim::scene3d::SceneDef& d) {
  std::ostringstream o;
  o << plural(d.bodies.size(), "body") << " (3D, free); forces:" << forcesOf(d, d.gravity != sim::world3d::Vec3::Zero())
    << "; " << plural(d.events.size(), "impulse event") << "; integrator "
    << sim::world3d::kIntegratorNames.name(d.integrator) << (d.normalize ? " (q normalized after each step)" : " (q left unnormalized)")
    << ", dt " << formatNumber(d.dt) << " s, duration " << formatNumber(d.duration) << " s";
  return o.str();
}

// the run and its expect entries; false when one fails
bool runCase3d(const sim::scene3d::SceneDef& def, sim::world3d::World& w, RunProgress3& progress) {
  if (def.expects.empty()) {
    // still run it: a scene that diverges is not a good scene
    w.advanceTo(def.duration, progress.observer());
    progress.finish();
    std::cout << "  ran to t = " << formatNumber(def.duration) << " (no expect entries)\n";
    return true;
  }
  const std::vector<sim::core::CheckResult> results = sim::scene3d::runExpects(def, w, progress.observer());
  progress.finish();
  return report(results);
}

// one variant of a 3D scene ("" for the base); false when an expect fails
bool checkCase3d(const std::string& file, const std::string& variant) {
  const sim::scene3d::SceneDef def = readSceneFile3(file, variant).model();
  const std::string label = file + (variant.empty() ? "" : " [" + variant + "]");
  std::cout << label << ": " << describeModel3(def) << '\n';
  std::cout << "  contacts: none (3D scenes model free rigid bodies: nothing collides, bodies pass through each other)\n";
  sim::world3d::World w = sim::scene3d::buildWorld(def);
  RunProgress3 progress(label, def.duration);
  try {
    return runCase3d(def, w, progress);
  } catch (const sim::world3d::Diverged& d) {
    // named by the body's name, not its index
    throw std::runtime_error("the simulation diverged at t = " + formatNumber(d.time) + " (body '" + def.bodies[d.body].name +
                             "'); use a smaller dt or another integrator");
  }
}

int check(const std::vector<std::string>& files) {
  int code = kExitOk;
  for (const std::string& file : files) {
    try {
      if (isSceneFile3d(file)) {
        if (!check3d(file) && code == kExitOk) code = kExitFailure;
        continue;
      }
      const sim::scene::SceneDef base = readSceneFile(file).model();
      std::vector<std::string> cases = base.variantNames;
      if (cases.empty()) cases.push_back("");
      for (const std::string& v : cases)
        if (!checkCase(file, v) && code == kExitOk) code = kExitFailure;
    } catch (const sim::yaml::SceneError& e) {
      std::cerr << e.what() << '\n';
      code = kExitBadInput;
    } catch (const sim::world::Diverged& d) {
      std::cerr << file << ": the simulation diverged at t = " << formatNumber(d.time) << " (body #" << d.body
                << "); use a smaller dt or another integrator\n";
      if (code == kExitOk) code = kExitFailure;
    } catch (const sim::world3d::Diverged& d) {
      std::cerr << file << ": the simulation diverged at t = " << formatNumber(d.time) << " (body #" << d.body
                << "); use a smaller dt or another integrator\n";
      if (code == kExitOk) code = kExitFailure;
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error& e) {
      std::cerr << file << ": " << e.what() << '\n';
      if (code == kExitOk) code = kExitFailure;
    }
  }
  return code;
}

}  // namespace

bool check3d(const std::string& file) {
  std::vector<std::string> cases = readSceneFile3(file).model().variantNames;
  if (cases.empty()) cases.push_back("");
  bool ok = true;
  for (const std::string& v : cases) ok = checkCase3d(file, v) && ok;
  return ok;
}

void addCheckCommand(CLI::App& app, int& exitCode) {
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("check", "validate scenes and verify their expect entries");
  cmd->add_option("scenes", *files, "scene files (YAML)")->required();
  cmd->callback([files, &exitCode] { exitCode = runInterruptible("check", [&] { return check(*files); }); });
}

}  // namespace render::cli

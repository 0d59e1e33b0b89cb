// `rigidreel check`: load and validate scenes, say what model each uses, and compare every
// variant's `expect` entries with the simulation.
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

#include "render/cli/check_tally.h"
#include "render/cli/commands.h"
#include "render/cli/energy_report.h"
#include "sim/world/energy_ledger.h"
#include "sim/world3d/energy_ledger3d.h"
#include "render/cli/lecture_files.h"
#include "render/cli/output.h"
#include "render/cli/run_progress.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/video/render_plan.h"
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
  o << plural(d.bodies.size(), "body") << " (" << dynamic
    << " dynamic); forces:" << forcesOf(d, d.gravity != sim::core::Vec2::Zero()) << "; "
    << plural(d.events.size(), "impulse event") << "; integrator " << sim::core::integratorName(d.integrator) << ", dt "
    << formatNumber(d.dt) << " s, duration " << formatNumber(d.duration) << " s";
  return o.str();
}

std::string formatValues(const std::vector<double>& v) {
  if (v.size() == 1) return formatNumber(v[0]);
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatNumber(v[i]);
  return s + ")";
}

// each comparison with its error; the failed ones returned (for JUnit). With --quiet, the failed
// ones alone, each after the file and variant (`quietLabel`), since nothing else names them
std::vector<std::string> report(const std::vector<sim::core::CheckResult>& results, const std::string& quietLabel = "") {
  std::vector<std::string> failed;
  for (const sim::core::CheckResult& r : results) {
    const std::string line = "t = " + formatNumber(r.time) + "  " + r.quantity + " = " + formatValues(r.actual) + ", expected " +
                             formatValues(r.expected) + ", error " + formatNumber(r.error) + " (tolerance " +
                             formatNumber(r.tolerance) + ")";
    if (!r.passed()) failed.push_back(line);
    if (!quietLabel.empty() && r.passed()) continue;
    std::cout << quietLabel << (r.passed() ? "  ok    " : "  FAIL  ") << line << '\n';
  }
  return failed;
}

// say where the event method found impacts piling up and made the contact resting: once per pair
// (its first and last time, how many), or every record with `verbose`
void reportResting(const sim::scene::SceneDef& def, const sim::world::World& w, bool verbose, std::ostream& out) {
  if (verbose) {
    for (const sim::world::RestingRecord& r : w.resting) out << "  resting: " << describeResting(def, r) << '\n';
    return;
  }
  for (const RestingSpan& s : mergeResting(w.resting)) out << "  resting: " << describeResting(def, s) << '\n';
}

// say when `auto` went from the event method to the stack solver during the run, and why
void reportSwitch(const sim::scene::SceneDef& def, const sim::world::World& w, std::ostream& out) {
  if (w.methodSwitch()) out << "  switched: " << describeMethodSwitch(def, w) << '\n';
}

// with sim: {sleep: true}, how many of the dynamic bodies sleep at the end (sim/world/sleep.h)
void reportSleep(const sim::world::World& w, std::ostream& out) {
  if (!w.def().sleep) return;
  long dynamic = 0;
  for (const sim::core::Body& b : w.bodies) dynamic += !b.isStatic;
  out << "  sleep: on; " << w.sleepingBodies() << " of " << dynamic << " dynamic bodies asleep at the end";
  if (w.collisions() != sim::core::CollisionMethod::Sequential && w.collisions() != sim::core::CollisionMethod::SoftStep)
    out << " (only the stack solvers sleep; " << sim::core::collisionMethodName(w.collisions()) << " does not)";
  out << '\n';
}

// with sim: {precision: float}, that soft_step solves its contacts in floats
void reportPrecision(const sim::world::World& w, std::ostream& out) {
  if (w.def().precision == sim::world::Precision::Double) return;
  out << "  precision: " << sim::world::precisionName(w.def().precision) << " (soft_step's contact solve";
  if (w.collisions() != sim::core::CollisionMethod::SoftStep)
    out << "; " << sim::core::collisionMethodName(w.collisions()) << " solves in doubles";
  out << ")\n";
}

// why a run stopped before its duration, as `simulate` says it
std::string runFailure(const sim::scene::SceneDef& def, const sim::core::Diverged& d) {
  return "the simulation diverged at t = " + formatNumber(d.time) + ": body '" + def.bodies[d.body].name +
         "' has a non-finite state; try a smaller step (--dt " + formatNumber(def.dt / 4) +
         ") or another integrator (--integrator rk4)";
}

// one scene, one variant ("" for the base), run to its duration as `simulate` runs it; returns
// what failed (an expect entry, the run stopping before its end), nothing when it passed;
// `threads` (--threads) in place of the scene's sim: threads when given
std::vector<std::string> checkCase(const OpenScene& scene, const std::string& variant, const Verbosity& say,
                                   std::optional<int> threads) {
  const std::string& file = scene.path();
  sim::scene::SceneDef def = scene.read(variant).model();
  if (threads) def.threads = *threads;
  warnOfModel(def, file);
  const std::string label = file + (variant.empty() ? "" : " [" + variant + "]");
  // --quiet: only what failed, so the lines about the model and the run go nowhere
  std::ostream& out = say.quiet ? nowhere() : std::cout;
  out << label << ": " << describeModel(def) << '\n';
  sim::world::World w = startWorld(def, file);
  out << "  collisions: " << describeCollisionMethod(def, w) << '\n';
  RunProgress progress(label, def.duration, nullptr, !say.quiet);
  // where the run's energy goes, step by step (and its `energy_never_rises` entries checked on it)
  sim::world::EnergyLedger ledger(w, progress.observer());
  std::vector<sim::core::CheckResult> results;
  std::string failure;
  try {
    results = sim::scene::runExpects(def, w, &ledger);
    // on past the last entry to the duration: a scene that passes check must simulate and render
    w.advanceTo(def.duration, &ledger);
  } catch (const sim::core::Diverged& d) {
    failure = runFailure(def, d);
  } catch (const sim::world::ImpactsPileUp& e) {
    failure = e.what();
  }
  progress.finish();
  std::vector<std::string> failures = report(results, say.quiet ? label + ":" : "");
  if (failure.empty()) {
    out << "  ran to t = " << formatNumber(def.duration) << (def.expects.empty() ? " (no expect entries)" : "");
    if (!w.impacts.empty()) out << ", " << w.impacts.size() << " impulses";
    out << '\n';
  } else {
    out << "  FAIL  " << failure << '\n';
    std::cerr << label << ": " << failure << '\n';
  }
  if (say.verbose)
    for (const sim::world::ImpactRecord& r : w.impacts) out << "  impulse " << describeImpact(def, r) << '\n';
  reportResting(def, w, say.verbose, out);
  reportSwitch(def, w, out);
  out << "  " << describeLedger(accountsOf(ledger), namesOf(def)) << '\n';
  reportSleep(w, out);
  reportPrecision(w, out);
  if (!failure.empty()) failures.push_back(failure);
  return failures;
}

// what a 3D scene models: its bodies and planes, their forces and events, the integrator and whether
// q is normalized after each step
std::string describeModel3d(const sim::scene3d::SceneDef& d) {
  std::ostringstream o;
  o << plural(d.bodies.size(), "body") << " (3D)";
  if (!d.planes.empty()) o << ", " << plural(d.planes.size(), "plane");
  o << "; forces:" << forcesOf(d, d.gravity != sim::world3d::Vec3::Zero()) << "; " << plural(d.events.size(), "impulse event")
    << "; integrator " << sim::world3d::kIntegratorNames.name(d.integrator)
    << (d.normalize ? " (q normalized after each step)" : " (q left unnormalized)") << ", dt " << formatNumber(d.dt)
    << " s, duration " << formatNumber(d.duration) << " s";
  return o.str();
}

// one variant of a 3D scene ("" for the base), run to its duration; what failed (an expect entry,
// the run diverging before its end), nothing when it passed
std::vector<std::string> checkCase3d(const OpenScene& scene, const std::string& variant, const Verbosity& say) {
  const std::string& file = scene.path();
  const sim::scene3d::SceneDef def = scene.read3d(variant).model();
  const std::string label = file + (variant.empty() ? "" : " [" + variant + "]");
  std::ostream& out = say.quiet ? nowhere() : std::cout;
  out << label << ": " << describeModel3d(def) << '\n';
  sim::world3d::World w = startWorld3d(def, file);
  out << "  collisions: " << describeCollisionMethod(def, w) << '\n';
  RunProgress3d progress(label, def.duration, nullptr, !say.quiet);
  // where the run's energy goes, step by step (and its `energy_never_rises` entries checked on it)
  sim::world3d::EnergyLedger3d ledger(w, progress.observer());
  std::vector<sim::core::CheckResult> results;
  std::string failure;
  try {
    results = sim::scene3d::runExpects(def, w, &ledger);
    w.advanceTo(def.duration, &ledger);
  } catch (const sim::core::Diverged& d) {
    failure = divergedMessage(file, def, d);
  } catch (const sim::world3d::ContactPersists& p) {
    failure = contactPersistsMessage(def, p);
  }
  progress.finish();
  std::vector<std::string> failures = report(results, say.quiet ? label + ":" : "");
  if (failure.empty()) {
    out << "  ran to t = " << formatNumber(def.duration) << (def.expects.empty() ? " (no expect entries)" : "");
    if (!w.impacts.empty()) out << ", " << w.impacts.size() << " impulses";
    out << '\n';
  } else {
    out << "  FAIL  " << failure << '\n';
    std::cerr << failure << '\n';
  }
  if (w.methodSwitch()) out << "  switched: " << describeMethodSwitch(def, w) << '\n';
  out << "  " << describeLedger(accountsOf(ledger), namesOf(def)) << '\n';
  if (!failure.empty()) failures.push_back(failure);
  return failures;
}

// `--render`: every output the lecture pack makes of the scene planned as `lecture` plans it (each
// variant surveyed, its video's frames counted and named, its poster, the poll panels), nothing
// drawn; false when a variant diverges on the way. Throws sim::yaml::SceneError, UsageError
template <class Plan>
bool planned(const std::string& file, const std::function<Plan()>& plan) {
  try {
    const Plan p = plan();
    long frames = 0;
    for (const auto& v : p.videos) frames += v.frameCount;
    std::cout << "  render: " << plural(p.videos.size(), "video") << " (" << frames << " frames), "
              << plural(p.stills ? p.stills->shots.size() : 0, "panel sheet") << " planned\n";
    return true;
  } catch (const sim::core::Diverged& d) {
    std::cout << "  FAIL  render: the simulation diverged at t = " << formatNumber(d.time) << " while planning\n";
    std::cerr << file << ": the simulation diverged at t = " << formatNumber(d.time) << " while planning its outputs\n";
    return false;
  }
}

bool planRender(const OpenScene& scene) {
  const std::string& file = scene.path();
  const render::video::LectureRequest request{.root = "out/lecture", .file = file, .size = {}, .fps = {}};
  if (scene.is3d())
    return planned<render::video::RenderPlan3d>(file,
                                                [&] { return render::video::planLecture3d(lectureLoader3d(scene), request); });
  return planned<render::video::RenderPlan>(file, [&] { return render::video::planLecture(lectureLoader(scene), request); });
}

// the files as given, a directory as every *.yaml in it (as `lecture` reads it: its order.txt's order, else sorted)
std::vector<std::string> sceneFiles(const std::vector<std::string>& arguments) {
  std::vector<std::string> files;
  for (const std::string& a : arguments) {
    std::error_code error;
    if (!std::filesystem::is_directory(a, error)) {
      files.push_back(a);
      continue;
    }
    for (const std::string& f : lectureSceneFiles({a})) files.push_back(f);
  }
  return files;
}

// the options of a check beside its files
struct CheckOptions {
  bool render = false;
  std::optional<int> threads;
  std::string junit;
};

// the scene's failure that ends its file (bad input, a run that stopped), said on standard error and
// tallied; `code` the exit status it makes
void failScene(CheckTally& tally, const std::string& file, const std::string& message, int code, int& exitCode) {
  std::cerr << message << '\n';
  tally.failScene(file, message);
  if (code == kExitBadInput || exitCode == kExitOk) exitCode = code;
}

int check(const std::vector<std::string>& arguments, const Verbosity& say, const CheckOptions& o) {
  int code = kExitOk;
  CheckTally tally;
  for (const std::string& file : sceneFiles(arguments)) {
    tally.addScene();
    try {
      const OpenScene scene(file);
      if (scene.is3d()) {
        check3d(scene, say, tally);
      } else {
        // (the base scene read whole, as each variant is: a fault in it is reported though variants replace it)
        (void)scene.read();
        std::vector<std::string> cases = scene.variantNames();
        if (cases.empty()) cases.push_back("");
        for (const std::string& v : cases) tally.add(file, v, checkCase(scene, v, say, o.threads));
      }
      if (o.render && !planRender(scene)) tally.failLast("render: the simulation diverged while planning its outputs");
      if (tally.failed(file) && code == kExitOk) code = kExitFailure;
    } catch (const UsageError& e) {
      failScene(tally, file, file + ": " + e.what(), kExitBadInput, code);
    } catch (const sim::yaml::SceneError& e) {
      failScene(tally, file, e.what(), kExitBadInput, code);
    } catch (const sim::core::Diverged& d) {
      failScene(tally, file,
                file + ": the simulation diverged at t = " + formatNumber(d.time) + " (body #" + std::to_string(d.body) +
                    "); use a smaller dt or another integrator",
                kExitFailure, code);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error& e) {
      failScene(tally, file, file + ": " + e.what(), kExitFailure, code);
    }
  }
  // the line a CI log ends with (under --quiet, only when something failed: a quiet pass prints nothing)
  if (!say.quiet || code != kExitOk) std::cout << tally.summary() << '\n';
  if (!o.junit.empty()) tally.writeJunit(o.junit);
  return code;
}

}  // namespace

void check3d(const OpenScene& scene, const Verbosity& say, CheckTally& tally) {
  std::vector<std::string> cases = scene.read3d().model().variantNames;
  if (cases.empty()) cases.push_back("");
  for (const std::string& v : cases) tally.add(scene.path(), v, checkCase3d(scene, v, say));
}

void addCheckCommand(CLI::App& app, int& exitCode) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto say = std::make_shared<Verbosity>();
  auto output = std::make_shared<std::string>();
  auto o = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check", "validate scenes, run every variant to its duration and verify its expect entries");
  cmd->add_option("scenes", *files, "scene files (YAML) and directories of them (every *.yaml, sorted)")->required();
  cmd->add_option("-o,--output", *output,
                  "write the report to this file instead of standard output (errors stay on standard error)");
  say->addTo(*cmd, "only what failed: the failed expect entries and the errors",
             "also every impulse the collision response applied, and every resting and staying-in-contact record, not one line "
             "per pair");
  cmd->add_option(
         "--threads", o->threads,
         "soft_step: threads sharing each set of contacts, 1 to 64 (each scene's sim: threads; the same result with any)")
      ->check(CLI::Range(1, sim::core::settings::kMaxThreads));
  cmd->add_option("--junit", o->junit, "also write a JUnit XML file: one testcase per scene variant, its failures its message");
  cmd->add_flag("--render", o->render, "also plan every output the scene asks for (videos, posters, panels), drawing nothing");
  cmd->callback([files, say, output, o, &exitCode] {
    refusePrintedOutputs(*output, "", false, *files, o->junit);
    OutputFile report(*output);
    exitCode = runInterruptible("check", [&] { return check(*files, *say, *o); });
    // an interrupted check publishes no report
    if (exitCode != render::jobs::kExitInterrupted) report.commit();
  });
}

}  // namespace render::cli

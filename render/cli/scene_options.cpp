#include "render/cli/scene_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "render/cli/commands.h"
#include "render/jobs/json_writer.h"
#include "sim/core/settings.h"
#include "sim/core/step_limit.h"
#include "sim/scene/model_warnings.h"
#include "sim/scene/scene_build.h"
#include "sim/scene3d/contact_pairs.h"
#include "sim/world3d/method_models3d.h"
#include "sim/scene/step_limit.h"
#include "sim/yaml/scene_yaml.h"

namespace render::cli {
using namespace render::jobs;

void SceneOptions::addTo(CLI::App& command) {
  command.add_option("--variant", variant, "the named variant of the scene to run");
  command.add_option("--integrator", integrator, "explicit_euler, symplectic_euler, midpoint or rk4 (and splitting in 3D)");
  command.add_option("--dt", dt, "fixed time step in seconds");
  command.add_option("--collisions", collisions, "auto, none, event, isolated, sequential or soft_step");
  command.add_option("--substeps", substeps, "soft_step: substeps per step, 1 to 1000 (the scene's sim: substeps)");
  command.add_option(
      "--contact-hertz", contactHertz,
      "soft_step: contact stiffness in Hz, capped at a quarter of the substep rate (the scene's sim: contact_hertz)");
  command.add_option(
      "--threads", threads,
      "soft_step: threads sharing each set of contacts, 1 to 64 (the scene's sim: threads; the same result with any)");
  command.add_option("--precision", precision,
                     "soft_step: double or float, the numbers of its contact solve (the scene's sim: precision)");
}

const OpenScene& SceneOptions::open() const {
  if (!opened_ || opened_->path() != scene) opened_ = std::make_shared<const OpenScene>(scene);
  return *opened_;
}

SceneFile SceneOptions::load() const {
  SceneFile file = open().read(variant);
  sim::scene::SceneDef& def = file.model();
  if (!integrator.empty()) {
    const auto method = sim::core::integratorFromName(integrator);
    if (!method)
      throw UsageError("--integrator: unknown integrator '" + integrator +
                       "'; choose one of: " + sim::core::kIntegratorNames.list());
    def.integrator = *method;
    def.integratorLoc = {};
  }
  if (dt) {
    if (!(*dt > 0.0) || !std::isfinite(*dt)) throw UsageError("--dt: the time step must be a positive finite number");
    def.dt = *dt;
    if (const std::string over = sim::core::dtOverDuration(def.dt, def.duration); !over.empty())
      throw UsageError("--dt: " + over + "; choose a smaller step");
    if (const std::string over = sim::scene::stepsOverLimit(def, def.duration); !over.empty())
      throw UsageError("--dt: " + over + "; choose a larger step, or raise the scene's 'sim: {max_steps: N}'");
  }
  if (!collisions.empty()) {
    const auto method = sim::core::collisionMethodFromName(collisions);
    if (!method)
      throw UsageError("--collisions: unknown collision method '" + collisions +
                       "'; choose one of: " + sim::core::kCollisionMethodNames.list());
    def.collisions = *method;
    def.collisionsLoc = {};
  }
  // (as in the scene's sim: block, they change soft_step only)
  if (substeps) {
    if (*substeps < 1 || *substeps > 1000) throw UsageError("--substeps: give a whole number from 1 to 1000");
    def.substeps = *substeps;
  }
  if (contactHertz) {
    if (!(*contactHertz > 0.0) || !std::isfinite(*contactHertz))
      throw UsageError("--contact-hertz: the contact stiffness must be a positive finite number of Hz");
    def.contactHertz = *contactHertz;
  }
  if (threads) {
    if (*threads < 1 || *threads > sim::core::settings::kMaxThreads)
      throw UsageError("--threads: give a whole number from 1 to 64");
    def.threads = *threads;
  }
  if (!precision.empty()) {
    const auto p = sim::world::precisionFromName(precision);
    if (!p)
      throw UsageError("--precision: unknown precision '" + precision +
                       "'; choose one of: " + sim::world::kPrecisionNames.list());
    def.precision = *p;
  }
  warnOfModel(def, scene);
  return file;
}

SceneFile3d SceneOptions::load3d() const {
  SceneFile3d file = open().read3d(variant);
  sim::scene3d::SceneDef& def = file.model();
  if (!integrator.empty()) {
    const auto method = sim::world3d::kIntegratorNames.parse(integrator);
    if (!method)
      throw UsageError("--integrator: unknown integrator '" + integrator +
                       "'; choose one of: " + sim::world3d::kIntegratorNames.list());
    def.integrator = *method;
  }
  if (dt) {
    if (!(*dt > 0.0) || !std::isfinite(*dt)) throw UsageError("--dt: the time step must be a positive finite number");
    def.dt = *dt;
    if (const std::string over = sim::core::dtOverDuration(def.dt, def.duration); !over.empty())
      throw UsageError("--dt: " + over + "; choose a smaller step");
    if (const std::string over = sim::core::stepsOverLimit(def.dt, def.maxSteps, def.duration); !over.empty())
      throw UsageError("--dt: " + over + "; choose a larger step, or raise the scene's 'sim: {max_steps: N}'");
  }
  if (!collisions.empty()) {
    const auto method = sim::core::collisionMethodFromName(collisions);
    if (!method || !(*method == sim::core::CollisionMethod::Auto || sim::world3d::methodModel3d(*method)))
      throw UsageError("--collisions: " + scene + " is a 3D scene, which takes the collision methods auto, none, event " +
                       "and sequential; '" + collisions + "' is not one of them");
    def.collisions = *method;
    def.collisionsLoc = {};
    // the reader refused an unmodeled pair under the scene's own method; under this one, here
    if (const auto pair = sim::scene3d::unmodeledPair(def))
      throw UsageError("--collisions " + collisions + ": " + scene + ": " +
                       sim::scene3d::unmodeledPairMessage(def.bodies[pair->first].name, def.bodies[pair->second].name));
  }
  if (substeps || contactHertz || !precision.empty())
    throw UsageError(std::string(substeps       ? "--substeps"
                                 : contactHertz ? "--contact-hertz"
                                                : "--precision") +
                     ": " + scene + " is a 3D scene, which has no soft_step");
  return file;
}

render::video::LoadVariant SceneOptions::variantLoader() const {
  (void)open();  // before the copy, which shares the parse
  return [options = *this](const std::string& variant) {
    SceneOptions one = options;
    one.variant = variant;
    render::scene::Scene scene = one.load().scene;
    // each video's world started as check and lecture start it: overlapping bodies are bad input at
    // their line (exit 2), not a failed render (the base scene of variants is never drawn)
    if (!variant.empty() || scene.model.variantNames.empty()) (void)startWorld(scene.model, one.scene);
    return scene;
  };
}

render::video::LoadVariant3d SceneOptions::variantLoader3d() const {
  (void)open();
  return [options = *this](const std::string& variant) {
    SceneOptions one = options;
    one.variant = variant;
    return one.load3d().scene;
  };
}

void warnOfModel(const sim::scene::SceneDef& def, const std::string& file) {
  // (once per warning and run: a render loads its variant again for each of its passes)
  static std::mutex lock;
  static std::set<std::string> said;
  for (const sim::scene::ModelWarning& w : sim::scene::modelWarnings(def)) {
    const std::string where = w.loc.line > 0 ? file + ":" + std::to_string(w.loc.line) + ":" + std::to_string(w.loc.column)
                                             : file + ": --" + w.setting + " " + w.value;
    const std::string line = where + ": warning: " + (w.loc.line > 0 ? "'" + w.setting + ": " + w.value + "': " : "") + w.message;
    const std::lock_guard<std::mutex> hold(lock);
    if (said.insert(line).second) std::cerr << line << '\n';
  }
  // more threads than cores take turns on them, and every step waits for the last: 64 threads on 2
  // cores ran 65 times slower than one (on a step large enough to share: settings.h's kContactsPerThread)
  const unsigned cores = std::thread::hardware_concurrency();
  if (def.collisions == sim::core::CollisionMethod::SoftStep && cores > 0 && def.threads > static_cast<int>(cores)) {
    const std::string line = file + ": warning: soft_step runs " + std::to_string(def.threads) + " threads on " +
                             std::to_string(cores) + (cores == 1 ? " core" : " cores") + " once a step has " +
                             std::to_string(sim::core::settings::kContactsPerThread) +
                             " contacts for each thread past the first, taking turns, and each step waits for all of "
                             "them (slower than one thread); give at most " +
                             std::to_string(cores) + " (sim: threads, --threads)";
    const std::lock_guard<std::mutex> hold(lock);
    if (said.insert(line).second) std::cerr << line << '\n';
  }
}

sim::world::World startWorld(const sim::scene::SceneDef& def, const std::string& file) {
  sim::world::World world = sim::scene::buildWorld(def);
  try {
    world.start();
  } catch (const sim::world::InitialOverlap& o) {
    std::ostringstream m;
    m << "bodies '" << def.bodies[o.a].name << "' and '" << def.bodies[o.b].name << "' overlap by " << o.depth
      << " at t = 0; the event method starts from separated bodies: move them apart, or choose "
         "--collisions sequential";
    const sim::core::SourceLoc at = def.bodies[o.b].loc;
    throw sim::yaml::SceneError(file, at.line, at.column, m.str());
  }
  return world;
}

namespace {

// the method, why, and when `auto` switched, alike in 2D and 3D
std::string describeMethod(sim::core::CollisionMethod method, sim::core::MethodReason reason,
                           const std::optional<sim::core::MethodSwitch>& switched, const NameOf& nameOf);

std::string describeSwitch(sim::core::CollisionMethod method, const std::optional<sim::core::MethodSwitch>& switched,
                           const NameOf& nameOf) {
  if (!switched) return "";
  const sim::core::MethodSwitch& w = *switched;
  namespace settings = sim::core::settings;
  // (a time on the step grid, k·dt, to the digits that tell it: 0.576, not 0.5760000000000001)
  char time[32];
  const auto end = std::to_chars(time, time + sizeof time, w.time, std::chars_format::general, 9).ptr;
  const std::string from =
      "event until t = " + std::string(time, end) + " s, then " + std::string(sim::core::collisionMethodName(method)) + ": ";
  if (w.a < 0) return from + "impacts piled up in one step (a stack forming)";
  const std::string pair = "'" + nameOf(w.a) + "' and '" + nameOf(w.b) + "'";
  switch (w.how) {
    case sim::core::Persistence::Rested: return from + pair + " stayed in contact (too slow to part after an impact)";
    case sim::core::Persistence::Rattling:
      return from + pair + " struck each other " + std::to_string(settings::kRepeatedImpacts) + " times within " +
             render::jobs::formatNumber(settings::kRepeatWindow) + " s, each slower than " +
             render::jobs::formatNumber(settings::kRepeatSpeed) + " m/s";
  }
  return from + pair;
}

std::string describeMethod(sim::core::CollisionMethod method, sim::core::MethodReason reason,
                           const std::optional<sim::core::MethodSwitch>& switched, const NameOf& nameOf) {
  std::string s(sim::core::collisionMethodName(method));
  switch (reason) {
    case sim::core::MethodReason::Requested: return s + " (as the scene or the command line asks)";
    case sim::core::MethodReason::FewBodies: return s + " (auto: no two bodies can meet, so no collision model is needed)";
    case sim::core::MethodReason::IsolatedImpacts:
      return s + " (auto: no bodies touch at the start, so impacts are isolated and can be resolved exactly)";
    case sim::core::MethodReason::PersistentContacts:
      return s + " (auto: bodies touch at the start under load, so contacts persist and need the iterative solver)";
    case sim::core::MethodReason::StackFormed:
    case sim::core::MethodReason::ContactPersisted: return s + " (auto: " + describeSwitch(method, switched, nameOf) + ")";
  }
  return s;
}

}  // namespace

NameOf namesOf(const sim::scene::SceneDef& def) {
  return [&def](int i) { return def.bodies[i].name; };
}

NameOf namesOf(const sim::scene3d::SceneDef& def) {
  return [&def](int i) { return i >= 0 ? def.bodies[i].name : def.planes[-1 - i].name; };
}

std::string describeCollisionMethod(const sim::scene::SceneDef& def, const sim::world::World& world) {
  return describeMethod(world.collisions(), world.methodReason(), world.methodSwitch(), namesOf(def));
}

std::string describeCollisionMethod(const sim::scene3d::SceneDef& def, const sim::world3d::World& world) {
  return describeMethod(world.collisions(), world.methodReason(), world.methodSwitch(), namesOf(def));
}

std::string describeMethodSwitch(const sim::scene::SceneDef& def, const sim::world::World& world) {
  return describeSwitch(world.collisions(), world.methodSwitch(), namesOf(def));
}

std::string describeMethodSwitch(const sim::scene3d::SceneDef& def, const sim::world3d::World& world) {
  return describeSwitch(world.collisions(), world.methodSwitch(), namesOf(def));
}

std::string describeResting(const sim::scene::SceneDef& def, const sim::world::RestingRecord& r) {
  return describeResting(def, RestingSpan{r, r.t, 1});
}

std::vector<RestingSpan> mergeResting(const std::vector<sim::world::RestingRecord>& records) {
  std::vector<RestingSpan> spans;
  for (const sim::world::RestingRecord& r : records) {
    auto same = std::find_if(spans.begin(), spans.end(), [&](const RestingSpan& s) {
      return s.first.a == r.a && s.first.b == r.b && s.first.moving == r.moving;
    });
    if (same == spans.end()) {
      spans.push_back({r, r.t, 1});
      continue;
    }
    same->last = r.t;
    ++same->count;
  }
  return spans;
}

std::string describeResting(const sim::scene::SceneDef& def, const RestingSpan& s) {
  const sim::world::RestingRecord& r = s.first;
  const std::string pair = "'" + def.bodies[r.a].name + "' and '" + def.bodies[r.b].name + "'";
  const std::string t = render::jobs::formatNumber(r.t);
  const std::string until = s.count > 1 ? " to " + render::jobs::formatNumber(s.last) : "";
  const std::string times = s.count > 1 ? std::to_string(s.count) + " times; " : "";
  if (r.moving)
    return pair + " stay in contact from t = " + t + until + " (" + times + "impacts piled up; they keep moving while touching)";
  return pair + " came to rest at t = " + t + until + " (" + times + "impacts piled up; the contact now rests)";
}

std::string describeImpact(const sim::scene::SceneDef& def, const sim::world::ImpactRecord& r) {
  using render::jobs::formatNumber;
  const auto pair = [](const sim::core::Vec2& v) { return "(" + formatNumber(v.x()) + ", " + formatNumber(v.y()) + ")"; };
  return "t = " + formatNumber(r.t) + ": '" + def.bodies[r.a].name + "' and '" + def.bodies[r.b].name + "' at " + pair(r.point) +
         ", normal " + pair(r.normal) + ", j = " + formatNumber(r.impulse) + ", tangent j = " + formatNumber(r.tangentImpulse) +
         ", v_n " + formatNumber(r.vnBefore) + " -> " + formatNumber(r.vnAfter);
}

}  // namespace render::cli

// `rigidreel simulate`: run a scene to a time and print its state (text or --json), optionally
// writing every step to a CSV trace.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "render/cli/commands.h"
#include "render/cli/energy_report.h"
#include "sim/world/energy_ledger.h"
#include "render/cli/output.h"
#include "render/cli/run_fields.h"
#include "render/cli/run_progress.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/trace/trace_writer.h"
#include "sim/scene/scene_build.h"
#include "sim/scene/step_limit.h"
#include "sim/world/diagnostics.h"

namespace render::cli {
using namespace render::jobs;

namespace {

struct SimulateOptions : SceneOptions, Verbosity {
  std::optional<double> until;
  bool json = false;
  std::string trace;
  std::string output;  // -o: the state into this file instead of standard output
};

// each body's pose, velocity and kinetic energy, by name
void writeBodies(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w) {
  j.key("bodies").beginArray();
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const sim::core::Body& b = w.bodies[i];
    j.beginObject()
        .field("name", def.bodies[i].name)
        .field("x", b.x.x())
        .field("y", b.x.y())
        .field("angle", b.angle)
        .field("vx", b.v.x())
        .field("vy", b.v.y())
        .field("omega", b.omega)
        .field("kinetic_energy", sim::world::kineticEnergy(b).total())
        .endObject();
  }
  j.endArray();
}

// the whole system's energy and momenta, and the ledger of where the energy went
void writeTotals(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w,
                 const sim::world::EnergyLedger& ledger) {
  const sim::world::Energy e = sim::world::energy(w);
  j.key("energy").beginObject().field("kinetic", e.kinetic).field("potential", e.potential).field("total", e.total()).endObject();
  const sim::core::Vec2 p = sim::world::linearMomentum(w);
  j.key("momentum").beginArray().value(p.x()).value(p.y()).endArray();
  j.field("angular_momentum", sim::world::angularMomentum(w));
  writeLedger(j, accountsOf(ledger), namesOf(def));
}

// the collision method and why; the optional fields only where they apply, so that the JSON of
// a run without them is unchanged
void writeMethod(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w) {
  j.field("collision_method", sim::core::collisionMethodName(w.collisions()));
  j.field("collision_method_reason", describeCollisionMethod(def, w));
  // only when `auto` switched to the stack solver during the run
  if (w.methodSwitch())
    j.field("collision_method_switch_time", w.methodSwitch()->time)
        .field("collision_method_switch", describeMethodSwitch(def, w));
  // only with sim: {sleep: true}: how many bodies sleep at the end (sim/world/sleep.h)
  if (w.def().sleep) j.field("sleep", true).field("sleeping_bodies", static_cast<long>(w.sleepingBodies()));
  // only with sim: {precision: float}
  if (w.def().precision != sim::world::Precision::Double) j.field("precision", sim::world::precisionName(w.def().precision));
}

// a vector as [x, y]
JsonWriter& writePair(JsonWriter& j, const sim::core::Vec2& v) { return j.beginArray().value(v.x()).value(v.y()).endArray(); }

// every impulse the collision response applied; b is the obstacle for a body–obstacle collision
void writeImpacts(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w) {
  j.key("collisions").beginArray();
  for (const sim::world::ImpactRecord& r : w.impacts) {
    j.beginObject().field("t", r.t).field("a", def.bodies[r.a].name).field("b", def.bodies[r.b].name);
    j.key("point");
    writePair(j, r.point);
    j.key("normal");
    writePair(j, r.normal);
    j.field("impulse", r.impulse).field("tangent_impulse", r.tangentImpulse);
    j.field("vn_before", r.vnBefore).field("vn_after", r.vnAfter).endObject();
  }
  j.endArray();
}

// the touching pairs at the end time
void writeContacts(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w) {
  j.key("contacts").beginArray();
  for (const sim::world::Contact& c : w.findContacts(sim::core::settings::kContactMargin)) {
    j.beginObject().field("a", def.bodies[c.a].name).field("b", def.bodies[c.b].name);
    j.key("normal");
    writePair(j, c.manifold.normal);
    j.key("points").beginArray();
    for (int k = 0; k < c.manifold.count; ++k) {
      j.beginObject().key("point");
      writePair(j, c.manifold.points[k].point);
      j.field("separation", c.manifold.points[k].separation).endObject();
    }
    j.endArray().endObject();
  }
  j.endArray();
}

// contacts the event method turned into resting contact (impacts piling up in finite time): one
// entry per pair and kind, from its first record (t) to its last, or every record with --verbose
void writeResting(JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::World& w, bool verbose) {
  j.key("resting").beginArray();
  std::vector<RestingSpan> spans;
  if (verbose)
    for (const sim::world::RestingRecord& r : w.resting) spans.push_back({r, r.t, 1});
  else spans = mergeResting(w.resting);
  for (const RestingSpan& s : spans)
    j.beginObject()
        .field("t", s.first.t)
        .field("a", def.bodies[s.first.a].name)
        .field("b", def.bodies[s.first.b].name)
        .field("moving", s.first.moving)
        .field("last", s.last)
        .field("count", s.count)
        .endObject();
  j.endArray();
}

void printJson(const sim::scene::SceneDef& def, const sim::world::World& w, const sim::world::EnergyLedger& ledger,
               bool verbose) {
  JsonWriter j(std::cout);
  j.beginObject();
  writeRunFields(j, def, w, sim::core::integratorName(w.def().integrator));
  writeBodies(j, def, w);
  writeTotals(j, def, w, ledger);
  writeMethod(j, def, w);
  writeImpacts(j, def, w);
  writeContacts(j, def, w);
  writeResting(j, def, w, verbose);
  j.endObject();
  std::cout << '\n';
}

void printText(const sim::scene::SceneDef& def, const sim::world::World& w, const sim::world::EnergyLedger& ledger,
               bool verbose) {
  std::cout << def.name << (def.variant.empty() ? "" : " [" + def.variant + "]") << ": t = " << formatNumber(w.time) << ", "
            << sim::core::integratorName(w.def().integrator) << ", dt = " << formatNumber(w.def().dt) << ", " << w.steps
            << " steps\n";
  std::cout << std::left << std::setw(16) << "body" << std::right;
  for (const char* h : {"x", "y", "angle", "vx", "vy", "omega", "kinetic"}) std::cout << std::setw(14) << h;
  std::cout << '\n';
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const sim::core::Body& b = w.bodies[i];
    std::cout << std::left << std::setw(16) << def.bodies[i].name << std::right << std::setprecision(6);
    for (double x : {b.x.x(), b.x.y(), b.angle, b.v.x(), b.v.y(), b.omega, sim::world::kineticEnergy(b).total()})
      std::cout << std::setw(14) << x;
    std::cout << '\n';
  }
  const sim::world::Energy e = sim::world::energy(w);
  const sim::core::Vec2 p = sim::world::linearMomentum(w);
  std::cout << std::setprecision(10) << "energy: kinetic " << e.kinetic << ", potential " << e.potential << ", total "
            << e.total() << "\nmomentum: (" << p.x() << ", " << p.y()
            << "), angular momentum about the origin: " << sim::world::angularMomentum(w) << '\n';
  std::cout << describeLedger(accountsOf(ledger), namesOf(def)) << '\n';
  std::cout << "collisions: " << describeCollisionMethod(def, w) << "; " << w.impacts.size() << " impulses applied";
  if (verbose)
    for (const sim::world::RestingRecord& r : w.resting) std::cout << "; " << describeResting(def, r);
  else
    for (const RestingSpan& s : mergeResting(w.resting)) std::cout << "; " << describeResting(def, s);
  std::cout << '\n';
  if (verbose)
    for (const sim::world::ImpactRecord& r : w.impacts) std::cout << "  impulse " << describeImpact(def, r) << '\n';
}

int simulate(const SimulateOptions& o) {
  refusePrintedOutputs(o.output, o.trace, o.quiet, {o.scene});
  const SilencedOutput silenced(o.quiet);
  OutputFile output(o.output);
  if (o.is3d()) {
    const int code = simulate3d(o, o.until, o.json, o.trace);
    if (code == kExitOk) output.commit();
    return code;
  }
  const sim::scene::SceneDef def = o.load().model();
  const double until = o.until.value_or(def.duration);
  if (!(until >= 0.0) || !std::isfinite(until))
    throw UsageError("--until: the end time must be zero or a positive finite number");
  if (const std::string over = sim::scene::stepsOverLimit(def, until); !over.empty())
    throw UsageError("--until: " + over + "; choose an earlier end, or raise the scene's 'sim: {max_steps: N}'");
  sim::world::World world = startWorld(def, o.scene);

  std::unique_ptr<AtomicFile> traceFile;
  std::unique_ptr<render::trace::TraceWriter> trace;
  if (!o.trace.empty()) {
    refuseInputAsOutput(o.trace, o.scene, "--trace");
    traceFile = openTrace(o.trace);
    trace = std::make_unique<render::trace::TraceWriter>(traceStream(traceFile), def);
    trace->rows(world);
  }
  // where the run's energy goes, step by step
  std::optional<sim::world::EnergyLedger> ledger;
  try {
    RunProgress progress(o.scene, until, trace.get(), !o.quiet);
    world.advanceTo(until, &ledger.emplace(world, progress.observer()));
  } catch (const sim::core::Diverged& d) {
    std::cerr << o.scene << ": the simulation diverged at t = " << formatNumber(d.time) << ": body '" << def.bodies[d.body].name
              << "' has a non-finite state; try a smaller step (--dt " << formatNumber(def.dt / 4)
              << ") or another integrator (--integrator rk4)\n";
    return kExitFailure;
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    std::cerr << o.scene << ": " << e.what() << '\n';
    return kExitFailure;
  }
  // a state that stayed finite can still make energies past a double's range (gravity 1e308)
  const sim::world::Energy e = sim::world::energy(world);
  const sim::core::Vec2 p = sim::world::linearMomentum(world);
  if (!std::isfinite(e.total()) || !p.allFinite() || !std::isfinite(sim::world::angularMomentum(world))) {
    std::cerr << o.scene << ": the simulation diverged: at t = " << formatNumber(world.time)
              << " its energy or momentum is not a finite number (a mass, speed or gravity past a double's range); "
                 "choose smaller values\n";
    return kExitFailure;
  }
  if (traceFile) traceFile->commit();
  o.json ? printJson(def, world, *ledger, o.verbose) : printText(def, world, *ledger, o.verbose);
  output.commit();
  return kExitOk;
}

}  // namespace

void addSimulateCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand("simulate", "run a scene and print the state at the end time");
  cmd->add_option("scene", options->scene, "the scene file (YAML)")->required();
  options->SceneOptions::addTo(*cmd);
  cmd->add_option("--until", options->until, "end time in seconds (default: the scene's duration)");
  cmd->add_flag("--json", options->json, "print one JSON object");
  cmd->add_option("--trace", options->trace, "write every step to this CSV file");
  cmd->add_option("-o,--output", options->output, "write the state (text or --json) to this file instead of standard output");
  options->Verbosity::addTo(*cmd, "print nothing (the exit status, and --trace's file); errors still on standard error",
                            "also every impulse the collision response applied, one a line (the text form; --json has them "
                            "all), and every resting and staying-in-contact record, not one per pair");
  cmd->callback(
      [options, &exitCode] { exitCode = runInterruptible("simulate " + options->scene, [&] { return simulate(*options); }); });
}

}  // namespace render::cli

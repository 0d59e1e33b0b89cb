// `rigidreel simulate` of a 3D scene: the state at the end time as text or one JSON object (every
// body's position, orientation [w, x, y, z], velocity, angular velocity and angular momentum, world
// frame; the energies and momenta of the whole scene), and every step as a CSV trace.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <memory>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/run_fields.h"
#include "render/cli/run_progress.h"
#include "render/cli/space3d.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/json_writer.h"
#include "render/trace/trace_writer.h"
#include "sim/core/step_limit.h"
#include "sim/scene3d/scene_build.h"
#include "sim/world3d/diagnostics.h"
#include "sim/world3d/energy_ledger3d.h"
#include "sim/yaml/yaml_reader.h"

namespace render::cli {
using namespace render::jobs;
using namespace sim::world3d;

namespace {

JsonWriter& vector3(JsonWriter& j, const Vec3& v) { return j.beginArray().value(v.x()).value(v.y()).value(v.z()).endArray(); }

void printJson(const sim::scene3d::SceneDef& def, const World& w, const EnergyLedger3d& ledger) {
  JsonWriter j(std::cout);
  j.beginObject();
  writeRunFields(j, def, w, kIntegratorNames.name(w.def().integrator));
  j.key("bodies").beginArray();
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const Body& b = w.bodies[i];
    j.beginObject().field("name", def.bodies[i].name);
    vector3(j.key("position"), b.x);
    j.key("orientation").beginArray().value(b.q.w()).value(b.q.x()).value(b.q.y()).value(b.q.z()).endArray();
    vector3(j.key("velocity"), b.v);
    vector3(j.key("angular_velocity"), b.omega);
    vector3(j.key("angular_momentum"), b.angularMomentum());
    j.field("kinetic_energy", kineticEnergy(b).total()).endObject();
  }
  j.endArray();
  const Energy e = energy(w);
  j.key("energy").beginObject().field("kinetic", e.kinetic).field("potential", e.potential).field("total", e.total()).endObject();
  vector3(j.key("momentum"), linearMomentum(w));
  vector3(j.key("angular_momentum"), angularMomentum(w));
  writeLedger(j, accountsOf(ledger), namesOf(def));
  j.field("collision_method", sim::core::collisionMethodName(w.collisions()));
  j.field("collision_method_reason", describeCollisionMethod(def, w));
  // only when `auto` switched to sequential during the run
  if (w.methodSwitch())
    j.field("collision_method_switch_time", w.methodSwitch()->time)
        .field("collision_method_switch", describeMethodSwitch(def, w));
  const NameOf name = namesOf(def);
  // every impulse the collision response applied; b is the plane for a body–plane collision
  j.key("collisions").beginArray();
  for (const ImpactRecord3& r : w.impacts) {
    j.beginObject().field("t", r.t).field("a", name(r.a)).field("b", name(r.b));
    vector3(j.key("point"), r.point);
    vector3(j.key("normal"), r.normal);
    j.field("impulse", r.impulse);
    vector3(j.key("tangent_impulse"), r.tangentImpulse);
    j.field("vn_before", r.vnBefore).field("vn_after", r.vnAfter).endObject();
  }
  j.endArray();
  // the touching pairs at the end time
  j.key("contacts").beginArray();
  for (const Contact3& c : w.findContacts(sim::core::settings::kContactMargin)) {
    j.beginObject().field("a", name(c.a)).field("b", name(c.b));
    vector3(j.key("normal"), c.normal);
    j.key("points").beginArray();
    for (int k = 0; k < c.count; ++k) {
      vector3(j.beginObject().key("point"), c.points[k].point);
      j.field("separation", c.points[k].separation).endObject();
    }
    j.endArray().endObject();
  }
  j.endArray();
  j.endObject();
  std::cout << '\n';
}

std::string triple(const Vec3& v) {
  std::ostringstream o;
  o << std::setprecision(6) << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return o.str();
}

void printText(const sim::scene3d::SceneDef& def, const World& w, const EnergyLedger3d& ledger) {
  std::cout << def.name << (def.variant.empty() ? "" : " [" + def.variant + "]") << ": t = " << formatNumber(w.time) << ", "
            << kIntegratorNames.name(w.def().integrator) << (w.def().normalizeQuaternions ? "" : " (q unnormalized)")
            << ", dt = " << formatNumber(w.def().dt) << ", " << w.steps << " steps\n";
  for (size_t i = 0; i < w.bodies.size(); ++i) {
    const Body& b = w.bodies[i];
    std::cout << def.bodies[i].name << ": x = " << triple(b.x) << ", q = [" << std::setprecision(6) << b.q.w() << ", " << b.q.x()
              << ", " << b.q.y() << ", " << b.q.z() << "] (|q| = " << std::setprecision(10) << b.q.norm()
              << ")\n  v = " << triple(b.v) << ", omega = " << triple(b.omega) << ", L = " << triple(b.angularMomentum())
              << ", kinetic " << std::setprecision(10) << kineticEnergy(b).total() << '\n';
  }
  const Energy e = energy(w);
  std::cout << std::setprecision(10) << "energy: kinetic " << e.kinetic << ", potential " << e.potential << ", total "
            << e.total() << "\nmomentum: " << triple(linearMomentum(w))
            << ", angular momentum about the origin: " << triple(angularMomentum(w)) << '\n';
  std::cout << describeLedger(accountsOf(ledger), namesOf(def)) << '\n';
  std::cout << "collisions: " << describeCollisionMethod(def, w) << "; " << w.impacts.size() << " impulses applied\n";
}

}  // namespace

std::string divergedMessage(const std::string& file, const sim::scene3d::SceneDef& def, const sim::core::Diverged& d) {
  return file + ": the simulation diverged at t = " + formatNumber(d.time) + ": body '" + def.bodies[d.body].name +
         "' has a non-finite state; try a smaller step (--dt " + formatNumber(def.dt / 4) +
         ") or another integrator (--integrator " +
         (def.integrator == sim::world3d::Integrator::Splitting ? "rk4" : "splitting") + ")";
}

std::string contactPersistsMessage(const sim::scene3d::SceneDef& def, const ContactPersists& p) {
  const NameOf name = namesOf(def);
  const std::string where = p.a < 0 ? "" : "'" + name(p.a) + "' and '" + name(p.b) + "' ";
  return where + "at t = " + formatNumber(p.time) + ": " + p.what() +
         "; the event method resolves isolated impacts only: use 'sim: {collisions: sequential}' or 'auto' (--collisions)";
}

World startWorld3d(const sim::scene3d::SceneDef& def, const std::string& file) {
  World world = sim::scene3d::buildWorld(def);
  try {
    world.start();
  } catch (const ContactPersists& p) {
    const sim::core::SourceLoc at = def.bodies[p.a].loc;
    throw sim::yaml::SceneError(file, at.line, at.column,
                                "body '" + def.bodies[p.a].name + "' overlaps '" + namesOf(def)(p.b) +
                                    "' at t = 0; the event method starts from separated bodies: move them apart, or choose "
                                    "--collisions sequential");
  }
  return world;
}

int simulate3d(const SceneOptions& o, std::optional<double> until, bool json, const std::string& tracePath) {
  const sim::scene3d::SceneDef def = o.load3d().model();
  const double end = until.value_or(def.duration);
  if (!(end >= 0.0) || !std::isfinite(end)) throw UsageError("--until: the end time must be zero or a positive finite number");
  if (const std::string over = sim::core::stepsOverLimit(def.dt, def.maxSteps, end); !over.empty())
    throw UsageError("--until: " + over + "; choose an earlier end, or raise the scene's 'sim: {max_steps: N}'");
  World world = startWorld3d(def, o.scene);
  std::unique_ptr<AtomicFile> traceFile;
  std::unique_ptr<render::trace::TraceWriter3d> trace;
  if (!tracePath.empty()) {
    refuseInputAsOutput(tracePath, o.scene, "--trace");
    traceFile = openTrace(tracePath);
    trace = std::make_unique<render::trace::TraceWriter3d>(traceStream(traceFile), def);
    trace->rows(world);
  }
  // where the run's energy goes, step by step
  std::optional<EnergyLedger3d> ledger;
  try {
    RunProgress3d progress(o.scene, end, trace.get());
    world.advanceTo(end, &ledger.emplace(world, progress.observer()));
  } catch (const sim::core::Diverged& d) {
    std::cerr << divergedMessage(o.scene, def, d) << '\n';
    return kExitFailure;
  } catch (const ContactPersists& p) {
    std::cerr << o.scene << ": " << contactPersistsMessage(def, p) << '\n';
    return kExitFailure;
  }
  // a state that stayed finite can still make energies past a double's range
  if (!std::isfinite(energy(world).total()) || !linearMomentum(world).allFinite() || !angularMomentum(world).allFinite()) {
    std::cerr << o.scene << ": the simulation diverged: at t = " << formatNumber(world.time)
              << " its energy or momentum is not a finite number (a mass, speed or gravity past a double's range); "
                 "choose smaller values\n";
    return kExitFailure;
  }
  if (traceFile) traceFile->commit();
  json ? printJson(def, world, *ledger) : printText(def, world, *ledger);
  return kExitOk;
}

}  // namespace render::cli

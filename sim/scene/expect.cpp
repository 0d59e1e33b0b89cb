#include "sim/scene/expect.h"

#include <algorithm>
#include <cmath>

#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"
#include "sim/world/energy_ledger.h"

namespace sim::scene {
using sim::world::World;
using namespace sim::core;
using namespace sim::collision;
using namespace sim::world;

namespace {

CheckResult compare(const ExpectDef& e, std::string quantity, std::vector<double> expected, std::vector<double> actual) {
  CheckResult r = compareValues(e.time, e.tolerance, std::move(quantity), std::move(expected), std::move(actual));
  r.earlierRun = e.earlierRun;
  return r;
}

std::vector<double> pair(const Vec2& v) { return {v.x(), v.y()}; }

// `energy_never_rises` from the ledger of the run up to the entry's time
CheckResult neverRises(const ExpectDef& e, const SceneDef& def, const EnergyLedger& ledger) {
  return neverRisesResult(ledger, e.time, e.tolerance, settings::kTimeSnap * def.dt, e.earlierRun,
                          [&](int i) { return def.bodies[i].name; });
}

}  // namespace

std::vector<CheckResult> evaluate(const ExpectDef& e, const SceneDef& def, const World& world,
                                  const std::unordered_map<std::string, int>* indices) {
  std::vector<CheckResult> out;
  if (e.energyNeverRises) return out;  // a whole run's: runExpects checks it
  const int i = e.body.empty() ? -1 : !indices ? def.bodyIndex(e.body) : indices->count(e.body) ? indices->at(e.body) : -1;
  const std::string prefix = i < 0 ? "" : e.body + ".";
  if (i >= 0) {
    const Body& b = world.bodies[i];
    if (e.position) out.push_back(compare(e, prefix + "position", pair(*e.position), pair(b.x)));
    if (e.angle) out.push_back(compare(e, prefix + "angle", {*e.angle}, {b.angle}));
    if (e.velocity) out.push_back(compare(e, prefix + "velocity", pair(*e.velocity), pair(b.v)));
    if (e.angularVelocity) out.push_back(compare(e, prefix + "angular_velocity", {*e.angularVelocity}, {b.omega}));
  }
  const Energy en = energy(world);
  if (e.kineticEnergy) {
    const double k = i >= 0 ? kineticEnergy(world.bodies[i]).total() : en.kinetic;
    out.push_back(compare(e, prefix + "kinetic_energy", {*e.kineticEnergy}, {k}));
  }
  if (e.potentialEnergy) out.push_back(compare(e, "potential_energy", {*e.potentialEnergy}, {en.potential}));
  if (e.totalEnergy) out.push_back(compare(e, "total_energy", {*e.totalEnergy}, {en.total()}));
  if (e.momentum) out.push_back(compare(e, "momentum", pair(*e.momentum), pair(linearMomentum(world))));
  if (e.angularMomentum) out.push_back(compare(e, "angular_momentum", {*e.angularMomentum}, {angularMomentum(world)}));
  return out;
}

std::vector<CheckResult> runExpects(const SceneDef& def) {
  World world = buildWorld(def);
  return runExpects(def, world);
}

std::vector<CheckResult> runExpects(const SceneDef& def, World& world, sim::world::StepObserver* observer) {
  std::vector<const ExpectDef*> order;
  for (const ExpectDef& e : def.expects) order.push_back(&e);
  std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->time < b->time; });
  std::vector<CheckResult> out;
  const std::unordered_map<std::string, int> indices = def.bodyIndices();
  // the energy ledger sees every step when an entry asks that the energy never rise: the caller's
  // when it passed its own as the observer, else one of this run's
  std::optional<EnergyLedger> own;
  EnergyLedger* ledger = dynamic_cast<EnergyLedger*>(observer);
  for (const ExpectDef* e : order) {
    if (!e->energyNeverRises) continue;
    if (!ledger) observer = ledger = &own.emplace(world, observer);
    ledger->watch(e->tolerance);
  }
  for (const ExpectDef* e : order) {
    if (e->energyNeverRises) {
      world.advanceWithin(e->time, std::max(def.duration, e->time), observer);
      out.push_back(neverRises(*e, def, *ledger));
      continue;
    }
    // the run's own steps up to the entry (none split there: the run goes on to its duration as
    // `simulate` runs it), and a copy advanced to its time when it falls between two of them
    const double end = std::max(def.duration, e->time);
    world.advanceWithin(e->time, end, observer);
    if (std::abs(world.time - e->time) <= settings::kTimeSnap * world.def().dt) {
      for (CheckResult& r : evaluate(*e, def, world, &indices)) out.push_back(std::move(r));
      continue;
    }
    World between = world;
    between.advanceTo(e->time);
    for (CheckResult& r : evaluate(*e, def, between, &indices)) out.push_back(std::move(r));
  }
  return out;
}

}  // namespace sim::scene

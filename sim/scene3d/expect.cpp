#include "sim/scene3d/expect.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <limits>

#include "sim/scene3d/scene_build.h"
#include "sim/world3d/energy_ledger3d.h"
#include "sim/world3d/diagnostics.h"

namespace sim::scene3d {
using sim::core::CheckResult;
using namespace sim::world3d;

namespace {

std::vector<double> values(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
std::vector<double> values(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

// every body followed from the start of the run, step by step
// (and passes every step and event on to `next`, if any)
class Measuring : public StepObserver {
 public:
  Measuring(const World& w, StepObserver* next) : next_(next) {
    for (const Body& b : w.bodies) bodies.emplace_back(b, w.time);
  }
  void afterStep(const World& w) override {
    for (size_t i = 0; i < w.bodies.size(); ++i) bodies[i].add(w.bodies[i], w.time);
    if (next_) next_->afterStep(w);
  }
  void afterEvent(const World& w, const ImpulseEvent& e) override {
    if (next_) next_->afterEvent(w, e);
  }
  std::vector<FreeBodyMeasures> bodies;

 private:
  StepObserver* next_;
};

bool measuresRun(const ExpectDef& e) { return e.precessionRate || e.spacePrecessionRate || e.flipPeriod; }

}  // namespace

std::vector<CheckResult> evaluate(const ExpectDef& e, const SceneDef& def, const World& world,
                                  const std::vector<FreeBodyMeasures>& measures,
                                  const std::unordered_map<std::string, int>* indices) {
  std::vector<CheckResult> out;
  if (e.energyNeverRises) return out;  // a whole run's: runExpects checks it
  auto compare = [&](std::string quantity, std::vector<double> expected, std::vector<double> actual) {
    out.push_back(sim::core::compareValues(e.time, e.tolerance, std::move(quantity), std::move(expected), std::move(actual)));
    out.back().earlierRun = e.earlierRun;
  };
  const int i = e.body.empty() ? -1 : !indices ? def.bodyIndex(e.body) : indices->count(e.body) ? indices->at(e.body) : -1;
  const std::string prefix = i < 0 ? "" : e.body + ".";
  if (i >= 0) {
    const Body& b = world.bodies[i];
    if (e.position) compare(prefix + "position", values(*e.position), values(b.x));
    if (e.orientation) {
      // q and −q turn the body alike: the actual one is reported with the sign nearer the expected
      const Quat q = (b.q.coeffs() - e.orientation->coeffs()).norm() <= (b.q.coeffs() + e.orientation->coeffs()).norm()
                         ? b.q
                         : Quat(-b.q.coeffs());
      compare(prefix + "orientation", values(*e.orientation), values(q));
    }
    if (e.quaternionNorm) compare(prefix + "quaternion_norm", {*e.quaternionNorm}, {b.q.norm()});
    if (e.velocity) compare(prefix + "velocity", values(*e.velocity), values(b.v));
    if (e.angularVelocity) compare(prefix + "angular_velocity", values(*e.angularVelocity), values(b.omega));
    if (e.coneAngle) {
      const Vec3 l = b.angularMomentum();
      compare(prefix + "cone_angle", {*e.coneAngle}, {std::atan2(b.omega.cross(l).norm(), b.omega.dot(l))});
    }
    const FreeBodyMeasures& m = measures[i];
    if (e.precessionRate) compare(prefix + "precession_rate", {*e.precessionRate}, {m.precessionRate()});
    if (e.spacePrecessionRate) compare(prefix + "space_precession_rate", {*e.spacePrecessionRate}, {m.spacePrecessionRate()});
    if (e.flipPeriod) {
      // a period needs two sign changes of ω's middle-axis part; fewer is a failure that says so
      std::string name = prefix + "flip_period";
      if (m.signChanges() < 2)
        name += " (ω along the middle axis changed sign " + std::to_string(m.signChanges()) + " times; 2 are needed)";
      compare(name, {*e.flipPeriod}, {m.flipPeriod()});
    }
  }
  const Energy en = energy(world);
  if (e.kineticEnergy)
    compare(prefix + "kinetic_energy", {*e.kineticEnergy}, {i >= 0 ? kineticEnergy(world.bodies[i]).total() : en.kinetic});
  if (e.angularMomentum)
    compare(prefix + "angular_momentum", values(*e.angularMomentum),
            values(i >= 0 ? world.bodies[i].angularMomentum() : angularMomentum(world)));
  if (e.potentialEnergy) compare("potential_energy", {*e.potentialEnergy}, {en.potential});
  if (e.totalEnergy) compare("total_energy", {*e.totalEnergy}, {en.total()});
  if (e.momentum) compare("momentum", values(*e.momentum), values(linearMomentum(world)));
  return out;
}

std::vector<CheckResult> runExpects(const SceneDef& def) {
  World world = buildWorld(def);
  return runExpects(def, world);
}

std::vector<CheckResult> runExpects(const SceneDef& def, World& world, StepObserver* observer) {
  std::vector<const ExpectDef*> order;
  for (const ExpectDef& e : def.expects) order.push_back(&e);
  std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->time < b->time; });
  // the energy ledger sees every step when an entry asks that the energy never rise: the caller's
  // when it passed its own as the observer, else one of this run's
  std::optional<EnergyLedger3d> own;
  EnergyLedger3d* ledger = dynamic_cast<EnergyLedger3d*>(observer);
  for (const ExpectDef* e : order) {
    if (!e->energyNeverRises) continue;
    if (!ledger) observer = ledger = &own.emplace(world, observer);
    ledger->watch(e->tolerance);
  }
  // the run's measures cost a rotation and a few angles per body and step: only when asked for
  const bool measuring = std::any_of(order.begin(), order.end(), [](auto* e) { return measuresRun(*e); });
  Measuring measures(world, observer);
  std::vector<CheckResult> out;
  const std::unordered_map<std::string, int> indices = def.bodyIndices();
  // a plane is −1 − its index, as in a contact
  const auto nameOf = [&](int i) { return i >= 0 ? def.bodies[i].name : def.planes[-1 - i].name; };
  for (const ExpectDef* e : order) {
    world.advanceTo(e->time, measuring ? &measures : observer);
    if (e->energyNeverRises) {
      out.push_back(sim::core::neverRisesResult(*ledger, e->time, e->tolerance, 0.0, e->earlierRun, nameOf));
      continue;
    }
    for (CheckResult& r : evaluate(*e, def, world, measures.bodies, &indices)) out.push_back(std::move(r));
  }
  return out;
}

}  // namespace sim::scene3d

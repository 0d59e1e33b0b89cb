#include "render/analysis/stability.h"

#include <cmath>
#include <sstream>

#include "render/analysis/pyramid_rows.h"
#include "render/jobs/interrupt.h"
#include "sim/scene/scene_build.h"
#include "sim/scene/step_limit.h"

namespace render::analysis {

using Parameter = StabilityDef::Parameter;

double stabilityDuration(const sim::scene::SceneDef& def) { return std::max(def.duration, kMinimumSteps * def.dt); }

namespace {

// the scene's own value of the parameter, where a search starts
double startValue(const Study& study) {
  const sim::scene::SceneDef& def = study.model;
  const StabilityDef& s = study.stability;
  if (s.from > 0.0) return s.from;
  switch (s.parameter) {
    case Parameter::Dt: return def.dt;
    case Parameter::Speed: {
      const double v = def.bodies[def.bodyIndex(s.body)].velocity.norm();
      return v > 0.0 ? v : 1.0;
    }
    case Parameter::MassRatio: return 1.0;
    case Parameter::StackHeight: return 1.0;
    case Parameter::PyramidBase: return readPyramid(def.bodies).rows->base;
    case Parameter::Iterations: return 1.0;
    case Parameter::Substeps: return 1.0;
  }
  return 1.0;
}

MetricsOptions criteria(const Study& study) {
  const sim::scene::SceneDef& def = study.model;
  MetricsOptions o;
  // energy may only grow where nothing feeds it
  o.energy = def.events.empty() && def.pointForces.empty();
  o.stack = study.stability.stack;
  o.within = study.stability.within;
  // a stack held within a distance of its rest pose is judged by that distance: how deep its
  // contacts sink is part of it (soft_step's contacts give by design)
  o.penetration = def.bodies.size() > 1 && o.within <= 0.0;
  return o;
}

bool holdsOnce(const Study& study, RunMetrics& metrics) {
  sim::world::World w = sim::scene::buildWorld(study.model);
  const MetricsOptions o = criteria(study);
  try {
    metrics = measureRun(w, stabilityDuration(study.model), o);
  } catch (const render::jobs::Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    // the method cannot run the scene at all (impacts pile up, bodies start overlapping)
    metrics = {};
    metrics.failure = "method gives up";
    return false;
  }
  return holds(metrics, o);
}

}  // namespace

Study withParameter(const Study& study, double value, double phase) {
  Study changed = study;
  sim::scene::SceneDef& def = changed.model;
  const StabilityDef& s = changed.stability;
  switch (s.parameter) {
    case Parameter::Dt: def.dt = value; break;
    case Parameter::Speed: {
      sim::scene::BodyDef& b = def.bodies[def.bodyIndex(s.body)];
      const sim::core::Vec2 direction =
          b.velocity.norm() > 0.0 ? sim::core::Vec2(b.velocity.normalized()) : sim::core::Vec2::UnitX();
      b.velocity = value * direction;
      b.position -= phase * def.dt * b.velocity;
      break;
    }
    case Parameter::MassRatio: {
      sim::scene::BodyDef& b = def.bodies[def.bodyIndex(s.body)];
      const sim::scene::MassProperties mp = sim::scene::massProperties(b);
      b.mass = value * mp.mass;
      b.inertia = value * mp.inertia;
      break;
    }
    case Parameter::StackHeight: {
      // keep the first `value` dynamic bodies, in the order the scene lists them
      int kept = 0;
      std::vector<sim::scene::BodyDef> bodies;
      for (const sim::scene::BodyDef& b : def.bodies)
        if (b.isStatic || kept++ < static_cast<int>(std::lround(value))) bodies.push_back(b);
      def.bodies = bodies;
      def.expects.clear();
      break;
    }
    case Parameter::PyramidBase: {
      const PyramidReading pyramid = readPyramid(def.bodies);
      def.bodies = pyramidOfBase(def.bodies, *pyramid.rows, static_cast<int>(std::lround(value)));
      def.expects.clear();
      break;
    }
    case Parameter::Iterations: def.velocityIterations = static_cast<int>(std::lround(value)); break;
    case Parameter::Substeps: def.substeps = static_cast<int>(std::lround(value)); break;
  }
  return changed;
}

bool holdsAt(const Study& study, double value, RunMetrics& metrics) {
  // a fast body may meet an obstacle anywhere within a step: try eight phases
  const int phases = study.stability.parameter == Parameter::Speed ? 8 : 1;
  for (int k = 0; k < phases; ++k)
    if (!holdsOnce(withParameter(study, value, static_cast<double>(k) / phases), metrics)) return false;
  return true;
}

StabilityResult findBoundary(const Study& def) {
  const StabilityDef& s = def.stability;
  const bool integer = s.countsBodies() || s.fewest();
  const double phases = s.parameter == Parameter::Speed ? 8.0 : 1.0;
  // every run counts against the scene's max_steps: a scene that fails at every dt would otherwise
  // halve dt 40 times, each run twice as long as the one before
  double spent = 0.0;
  const auto run = [&](double value, RunMetrics& m) {
    const sim::scene::SceneDef at = withParameter(def, value).model;
    const double steps = phases * sim::scene::stepCount(at, stabilityDuration(at));
    if (spent + steps > def.model.maxSteps) throw BudgetSpent{};
    spent += steps;
    return holdsAt(def, value, m);
  };
  const double limit = s.to > 0.0 ? s.to : (integer ? 1000.0 : 1e12);
  // a pyramid's base grows by doubling (its runs cost the square of the base); a stack by one box
  const Growth growth = s.parameter == Parameter::StackHeight ? Growth::ByOne : Growth::Doubling;
  StabilityResult r =
      s.fewest() ? searchFewest(startValue(def), limit, run) : searchBoundary(startValue(def), limit, integer, run, growth);
  r.steps = spent;
  return r;
}

StabilityResult searchBoundary(double start, double limit, bool integer, const std::function<bool(double, RunMetrics&)>& holds,
                               Growth growth) {
  StabilityResult r;
  RunMetrics m;
  double good = start, bad = 0.0;
  bool held = false;
  try {
    // a value that holds: halve until one does
    for (int k = 0; !holds(good, m); ++k) {
      bad = good, r.failing = m;
      if (k == 40 || (integer && good <= 1.0)) {
        r.failsEverywhere = true;
        r.firstFailing = good;
        return r;
      }
      good = integer ? std::floor(good / 2.0) : good / 2.0;
    }
    held = true;
    // a value that fails: double until one does (or the limit holds too)
    if (bad == 0.0) {
      double next = good;
      for (int k = 0;; ++k) {
        next = std::min(growth == Growth::ByOne ? good + 1.0 : 2.0 * good, limit);
        if (!holds(next, m)) {
          bad = next, r.failing = m;
          break;
        }
        good = next;
        if (good >= limit || k == 60) {
          r.holdsToLimit = true;
          r.largestStable = good;
          return r;
        }
      }
    }
    // bisect the bracket
    while (integer ? bad - good > 1.0 : (bad - good) > 1e-3 * good) {
      const double mid = integer ? std::floor(0.5 * (good + bad)) : 0.5 * (good + bad);
      if (holds(mid, m)) good = mid;
      else bad = mid, r.failing = m;
    }
  } catch (const BudgetSpent&) {
    // what is known so far: the last value that held and the first that failed
    r.budgetSpent = true;
    r.failsEverywhere = !held && bad > 0.0;
    r.holdsToLimit = held && bad == 0.0;
  }
  r.largestStable = held ? good : 0.0;
  r.firstFailing = bad;
  return r;
}

StabilityResult searchFewest(double start, double limit, const std::function<bool(double, RunMetrics&)>& holds) {
  StabilityResult r;
  r.fewest = true;
  RunMetrics m;
  double good = 0.0, bad = 0.0;
  try {
    // a value that holds: double until one does (or the limit fails too)
    for (double n = start;; n = std::min(2.0 * n, limit)) {
      if (holds(n, m)) {
        good = n;
        break;
      }
      bad = n, r.failing = m;
      if (n >= limit) {
        r.failsEverywhere = true;
        r.firstFailing = bad;
        return r;
      }
    }
    if (bad == 0.0) r.holdsToLimit = true;
    // bisect down to the neighbour that fails
    while (bad > 0.0 && good - bad > 1.0) {
      const double mid = std::floor(0.5 * (good + bad));
      if (holds(mid, m)) good = mid;
      else bad = mid, r.failing = m;
    }
  } catch (const BudgetSpent&) {
    r.budgetSpent = true;
    r.failsEverywhere = good == 0.0 && bad > 0.0;
  }
  r.largestStable = good;
  r.firstFailing = bad;
  return r;
}

std::string describeFailure(const Study& study, const StabilityResult& r) {
  const sim::scene::SceneDef& def = study.model;
  return describeBoundary(std::string(sim::core::integratorName(def.integrator)) + " + " +
                              std::string(sim::core::collisionMethodName(def.collisions)),
                          kParameterNames.name(study.stability.parameter), r, def.maxSteps);
}

std::string describeBoundary(const std::string& method, std::string_view p, const StabilityResult& r, double maxSteps) {
  std::ostringstream o;
  o << method << ": ";
  std::ostringstream budget;
  if (r.budgetSpent)
    budget << "; the search stopped early, after " << r.steps << " steps, as the next run would pass the scene's "
           << "max_steps (" << maxSteps << "); raise it with 'sim: {max_steps: N}' to search further";
  if (r.holdsToLimit || (r.budgetSpent && r.firstFailing == 0.0)) {
    if (r.largestStable > 0.0) o << (r.fewest ? "holds from " : "holds up to ") << p << " = " << r.largestStable;
    else o << "no run fits in the budget";
    o << (r.budgetSpent ? budget.str() : r.fewest ? " (the fewest tried)" : " (the search's limit)");
    return o.str();
  }
  const RunMetrics& m = r.failing;
  const std::string failure = m.failure;
  if (failure == "energy grows")
    o << "energy +" << std::lround(100.0 * (m.energyEnd - m.energyStart) / std::max(std::abs(m.energyStart), m.energyScale))
      << " %";
  else if (failure == "non-finite state") o << "non-finite state at t = " << m.divergedAt;
  else if (failure == "tunneling") o << "tunneling (a body passes through another)";
  else if (failure == "stack drifts") o << "the top drifts " << std::lround(100.0 * m.topDrift) << " % of its size";
  else if (failure == "a body leaves its rest pose") o << "a body ends " << m.maxDisplacement << " m from its rest pose";
  else if (failure == "not at rest") o << "a body still moves at " << m.fastest << " m/s";
  else if (failure == "penetration") o << "penetration " << m.maxPenetration << " m (over 2 × slop)";
  else if (failure == "angular momentum drifts") o << "|L| drifts " << std::lround(100.0 * m.angularMomentumDrift) << " %";
  else if (failure == "quaternion drifts") o << "|q| drifts " << m.quaternionDrift << " from 1";
  else o << failure;
  o << " at " << p << " = " << r.firstFailing;
  if (r.failsEverywhere) o << " (fails at every value tried)";
  else o << (r.fewest ? "; holds from " : "; holds at ") << r.largestStable;
  o << budget.str();
  return o.str();
}

}  // namespace render::analysis

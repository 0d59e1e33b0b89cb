// The collision methods, one unit each, all declared here and chosen by name (Solver2D's solver.h:
// interchangeable solvers side by side on the same scenes). World::step calls the method's step;
// each method keeps its own state from step to step.
//
//   none        free_motion.cpp        bodies pass through each other
//   isolated    isolated_solver.cpp    the notes' impulse at each overlap after a fixed step
//   sequential  sequential_solver.cpp  sequential impulses, warm started (Catto 2006)
//   soft_step   soft_step_solver.cpp   soft contacts in substeps, relaxed (Box2D v3, Catto 2024)
//   event       event_stepper.cpp      exact: to each time of impact, the notes' impulse there
#pragma once

#include <memory>
#include <vector>

#include "sim/core/cloned.h"
#include "sim/core/integrators.h"
#include "sim/world/contact.h"

namespace sim::world {

class World;

// one step [start, start + h]; the world splits its steps at every impulse event and force switch
struct TimeStep {
  double start = 0.0;
  double h = 0.0;
  double end() const { return start + h; }
  // no force switches inside a step: the timed forces on at its midpoint are on for all of it
  double midpoint() const { return start + 0.5 * h; }
};

// a collision method: one step of the world, read top to bottom as the method's algorithm is
// written (Box2D-Lite's World::Step; Box2D v3's stage list for soft_step)
class Method {
 public:
  virtual ~Method() = default;
  virtual std::unique_ptr<Method> clone() const = 0;
  // once, before the first step (event: the bodies must start apart)
  virtual void start(World&) {}
  // the bodies from step.start to step.end(): their motion and every collision in it
  virtual void step(World&, const TimeStep&) = 0;
  // forces of the contacts the method holds, added to the applied ones at state y (event: resting
  // contacts push back so that they do not sink in)
  virtual void addContactForces(const World&, const sim::core::States& /*y*/, std::vector<sim::core::Vec2>& /*force*/,
                                std::vector<double>& /*torque*/) const {}
};

std::unique_ptr<Method> makeFreeMotion();
std::unique_ptr<Method> makeIsolatedSolver();
std::unique_ptr<Method> makeSequentialSolver();
// `precision`: the numbers of its contact solve
std::unique_ptr<Method> makeSoftStepSolver(Precision precision = Precision::Double);
std::unique_ptr<Method> makeEventStepper();
// the unit of a method by its name (`auto` must be resolved first: World::start)
std::unique_ptr<Method> makeMethod(sim::core::CollisionMethod method, Precision precision = Precision::Double);

// the free-body equations during one step, as the integrators see them (notes: "Dynamics of a free
// body"): the world's rates at the step's midpoint, whatever stage time the integrator asks for.
// A force switching at the step's end is on at all of the step's stages, as it is on all of its
// open interval (RK4's last stage at the end of the step included).
class StepDynamics : public sim::core::Dynamics {
 public:
  StepDynamics(const World& world, const TimeStep& step) : world_(world), midpoint_(step.midpoint()) {}
  void rates(double t, const sim::core::States& y, sim::core::Rates& out) const override;

 private:
  const World& world_;
  double midpoint_;
};

// every body moved by the integrator over the step, as if nothing touched (free_motion.cpp)
void moveFreely(World& world, const TimeStep& step);

// a method owned by value: a copy of the world has a copy of its method's state
using OwnedMethod = sim::core::Cloned<Method>;

}  // namespace sim::world

// The 3D collision methods, one unit each, chosen by name as in 2D (sim/world/methods.h):
//
//   none        moves the bodies by the integrator; they pass through each other and the planes
//   event       event3d.cpp        exact: to each time of impact, the notes' impulse there
//   sequential  sequential3d.cpp   sequential impulses, warm started (Catto 2006), in 3D
//
// What each models is method_models3d.h's table.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "sim/world3d/integrators.h"

namespace sim::world3d {

class World;

// a collision method: one step of the world from `start` by `h`, its motion and its collisions
class Method3 {
 public:
  virtual ~Method3() = default;
  virtual std::unique_ptr<Method3> clone() const = 0;
  // once, before the first step
  virtual void start(World&) {}
  virtual void step(World& world, double start, double h) = 0;
};

std::unique_ptr<Method3> makeFreeMotion3();
std::unique_ptr<Method3> makeEventStepper3();
std::unique_ptr<Method3> makeSequentialSolver3();

// every body moved by the integrator over [start, start + h], as if nothing touched (q then back
// onto unit length when the world normalizes)
void moveFreely(World& world, double start, double h);
// the states `from` moved by the integrator over τ within the step starting at `start` of length h
// (the forces on at its midpoint), as moveFreely moves them
States motion(const World& world, const States& from, double start, double h, double tau);

// the event method cannot carry a contact on: it persists (a body too slow to part from a plane or
// another, or impacts piling up in one step). `auto` hands the step to sequential; named, the run
// stops with this, which says what to use
struct ContactPersists : std::runtime_error {
  ContactPersists(double time, int a, int b, const std::string& why);
  double time;
  int a, b;
};

}  // namespace sim::world3d

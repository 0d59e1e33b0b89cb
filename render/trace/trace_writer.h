// The CSV trace of a run: one row per body after every step, and again after each event, from the
// state at the start on. `simulate --trace`, `render --trace` and `snapshot --trace` write it with
// this one writer, so that the same run gives the same bytes whichever command ran it.
#pragma once

#include <ostream>

#include "sim/scene/scene_def.h"
#include "sim/scene3d/scene_def.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::trace {

// a 2D run: t,body,x,y,angle,vx,vy,omega,kinetic_energy
class TraceWriter : public sim::world::StepObserver {
 public:
  // writes the header; `def` (the bodies' names) must outlive the writer
  TraceWriter(std::ostream& out, const sim::scene::SceneDef& def);
  void afterStep(const sim::world::World& w) override { rows(w); }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent&) override { rows(w); }
  // every body's row now (the run's start state, before it is observed)
  void rows(const sim::world::World& w);

 private:
  std::ostream& out_;
  const sim::scene::SceneDef& def_;
};

// a 3D run: t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy
class TraceWriter3d : public sim::world3d::StepObserver {
 public:
  TraceWriter3d(std::ostream& out, const sim::scene3d::SceneDef& def);
  void afterStep(const sim::world3d::World& w) override { rows(w); }
  void afterEvent(const sim::world3d::World& w, const sim::world3d::ImpulseEvent&) override { rows(w); }
  void rows(const sim::world3d::World& w);

 private:
  std::ostream& out_;
  const sim::scene3d::SceneDef& def_;
};

}  // namespace render::trace

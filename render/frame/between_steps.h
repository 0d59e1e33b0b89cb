// A picture of a run at any time without splitting the run's own steps (2D SceneRun and 3D
// SceneRun3d alike): the run advanced by its steps that end by t, then, when t falls between two of
// them, a copy of the run (its history too, so that an impact inside the part step shows) advanced
// to t. The run's trajectory is then the scene's own whatever the pictures' times.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "sim/core/settings.h"

namespace render::frame {

// `run` (a world and its history) advanced toward `end` as far as t allows, told to `observer`;
// returns the state to draw at t: `run` itself, or `between` (reused) advanced to t. A copy's part
// step that fails where the run does not (impacts piling up in a step cut short) gives `run`: the
// run meets its own failures in its own steps. Throws std::logic_error for t before the run's time.
template <class State, class Observer>
const State& reachBetween(State& run, std::unique_ptr<State>& between, double t, double end, Observer* observer) {
  auto& world = run.world;
  const double snap = sim::core::settings::kTimeSnap * world.dt;
  if (t < world.time - snap) throw std::logic_error("a picture earlier than the run's time");
  world.advanceWithin(t, std::max(t, end), observer);
  if (std::abs(world.time - t) <= snap) return run;
  if (!between) between = std::make_unique<State>(run);
  else *between = run;
  try {
    between->world.advanceTo(t, &between->history);
  } catch (const std::runtime_error&) {
    return run;
  }
  return *between;
}

}  // namespace render::frame

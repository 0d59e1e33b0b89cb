// What an `expect` entry checks alike in 2D and 3D, generic over the dimension's vector: a closed-form
// answer that `rigidreel check` compares against, at a time, of a body or of the world; absent fields
// are not checked. sim/scene's and sim/scene3d's ExpectDef add the rotation's quantities.
#pragma once

#include <optional>
#include <string>

#include "sim/core/force_defs.h"
#include "sim/core/settings.h"

namespace sim::core {

template <class Vec>
struct ExpectDefOf {
  double time = 0.0;
  std::string body;  // empty for world-wide quantities
  // the body's state at `time`
  std::optional<Vec> position, velocity;
  // energies (kinetic: the body's, or the world's without a body) and the world's momentum
  std::optional<double> kineticEnergy, potentialEnergy, totalEnergy;
  std::optional<Vec> momentum;
  // the energy, less the work of applied forces and impulse events, never rises by more than the
  // tolerance above its lowest value so far, at any step up to `time` (sim/core/energy_ledger_of.h)
  bool energyNeverRises = false;
  double tolerance = settings::kDefaultExpectTolerance;
  bool earlierRun = false;  // source: earlier_run, a value an earlier run gave (else a closed form)
  SourceLoc loc;
};

}  // namespace sim::core

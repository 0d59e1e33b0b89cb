// The energy ledger of a 3D run (sim/core/energy_ledger_of.h), as 2D's: where the energy went at
// impacts, in contacts, to damping and by the integrator, and the adjusted energy that
// `expect: {energy_never_rises}` is checked against.
#pragma once

#include "sim/core/energy_ledger_of.h"
#include "sim/world3d/diagnostics.h"
#include "sim/world3d/world.h"

namespace sim::world3d {

using EnergyLedger3d = sim::core::EnergyLedgerOf<World, StepObserver, ImpulseEvent, States>;

}  // namespace sim::world3d

// The energy ledger of a 2D run (sim/core/energy_ledger_of.h): where the energy went, step by
// step, and the adjusted energy that `expect: {energy_never_rises}` is checked against.
#pragma once

#include "sim/core/energy_ledger_of.h"
#include "sim/world/diagnostics.h"
#include "sim/world/world.h"

namespace sim::world {

using EnergyLedger = sim::core::EnergyLedgerOf<World, StepObserver, ImpulseEvent, sim::core::States>;

}  // namespace sim::world

// The energy ledger of a run (sim/core/energy_ledger_of.h), 2D or 3D, as `check` and `simulate`
// report it: in words, and as the JSON of `simulate --json`. Amounts below the run's round-off (a
// billionth of its largest energy) read 0, so round-off is never shown as a gain.
#pragma once

#include <functional>
#include <string>

#include "render/jobs/json_writer.h"
#include "sim/core/energy_ledger_of.h"

namespace render::cli {

// the accounts of a ledger of either dimension
struct LedgerAccounts {
  double start = 0, end = 0, lostAtImpacts = 0, lostInContacts = 0, lostToDamping = 0, lostByIntegrator = 0;
  double appliedWork = 0, eventWork = 0, gained = 0, scale = 0;
  sim::core::EnergyRise largestGain;
};
template <class Ledger>
LedgerAccounts accountsOf(const Ledger& l) {
  return {l.start,       l.end,       l.lostAtImpacts, l.lostInContacts, l.lostToDamping, l.lostByIntegrator,
          l.appliedWork, l.eventWork, l.gained,        l.scale,          l.largestGain};
}
// a body's name by its index (in 3D, a plane's by −1 − its index)
using NameOf = std::function<std::string(int)>;

// "energy: 4.91 J at the start, 2.45 J at the end; lost 2.4 J at impacts, ...; gained nothing"
std::string describeLedger(const LedgerAccounts& ledger, const NameOf& nameOf);
// the same as the "energy_ledger" object
void writeLedger(render::jobs::JsonWriter& j, const LedgerAccounts& ledger, const NameOf& nameOf);

}  // namespace render::cli

// The energy ledger of a run (sim/world/energy_ledger.h) as `check` and `simulate` report it: in
// words, and as the JSON of `simulate --json`. Amounts below the run's round-off (a billionth of its
// largest energy) read 0, so round-off is never shown as a gain.
#pragma once

#include <string>

#include "render/jobs/json_writer.h"
#include "sim/scene/scene_def.h"
#include "sim/world/energy_ledger.h"

namespace render::cli {

// "energy: 4.91 J at the start, 2.45 J at the end; lost 2.4 J at impacts, ...; gained nothing"
std::string describeLedger(const sim::scene::SceneDef& def, const sim::world::EnergyLedger& ledger);
// the same as the "energy_ledger" object
void writeLedger(render::jobs::JsonWriter& j, const sim::scene::SceneDef& def, const sim::world::EnergyLedger& ledger);

}  // namespace render::cli

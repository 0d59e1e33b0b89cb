// The fields every `simulate --json` object starts with, 2D or 3D alike (render/cli/README.md:
// simulate's JSON): the scene, its variant (null for none), the time reached, the integrator, dt
// and the steps taken.
#pragma once

#include <string_view>

#include "render/jobs/json_writer.h"

namespace render::cli {

template <class SceneDef, class World>
void writeRunFields(render::jobs::JsonWriter& j, const SceneDef& def, const World& w, std::string_view integrator) {
  j.field("scene", def.name);
  j.key("variant");
  def.variant.empty() ? j.null() : j.value(def.variant);
  j.field("t", w.time).field("integrator", integrator).field("dt", w.def().dt).field("steps", w.steps);
}

}  // namespace render::cli

// The `render:` block of a scene, as plain definitions (documented in scenes/README.md).
// The simulator never reads it; the renderer does.
#pragma once

namespace sim {

struct RenderDef {};

}  // namespace sim

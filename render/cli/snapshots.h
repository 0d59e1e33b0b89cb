// Still frames of a scene, as `rigidreel snapshot` writes them: at exact times or at its impacts,
// one PNG each, or every variant side by side in one labeled image (the poll slide). Shared by
// `snapshot` and `lecture`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/cli/scene_options.h"
#include "render/cli/videos.h"

namespace render::cli {

struct SnapshotOptions : SceneOptions {
  std::vector<double> times;  // s; empty with `impacts`
  bool impacts = false;
  bool panels = false;
  std::optional<int> strobe;
  std::string output = "out";
  std::string size;
};

// tells `wrote` each PNG once written; throws UsageError, sim::yaml::SceneError and sim::world::Diverged
void writeSnapshots(const SnapshotOptions& options, const Wrote& wrote);

}  // namespace render::cli

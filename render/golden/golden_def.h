// The scene file's `golden:` block: when `rigidreel golden record` takes frames and how closely
// `golden check` must match them (documented in scenes/README.md), read from the same YAML tree as
// the model.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sim::yaml {
struct SceneSource;
}

namespace render::golden {

// the scene's top-level key this block is read from
inline constexpr const char* kGoldenKey = "golden";

struct StateTolerance {
  double position = 1e-9;  // m
  double angle = 1e-9;     // rad
  double velocity = 1e-9;  // m/s and rad/s
};

struct GoldenDef {
  std::vector<double> at;         // s: the frames' times (empty: the scene's duration)
  bool impacts = true;            // a frame at each impact too (the first kMaxImpactFrames)
  int width = 640, height = 360;  // px of the golden frames
  StateTolerance tolerance;
  int pixelTolerance = 24;       // of 255: a pixel differs when a channel is off by more
  double pixelFraction = 0.002;  // a frame differs when more than this fraction of its pixels do
};

// the most impacts given a frame of their own
inline constexpr size_t kMaxImpactFrames = 8;

// the scene's golden: block (defaults when it has none); `duration` bounds the times. Throws
// sim::yaml::SceneError at the fault's FILE:LINE:COL.
GoldenDef readGolden(const sim::yaml::SceneSource& source, double duration);

}  // namespace render::golden

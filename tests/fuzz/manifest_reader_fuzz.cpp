// libFuzzer target: a golden record's manifest.json reader on any bytes. A SceneError at the fault is
// the expected answer to bad input; anything else (a crash, a sanitizer report, another exception)
// is a bug. What it reads must hold: checkpoints within the run and ascending, each frame at one
// of them, sizes a renderer can draw.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "render/golden/record_manifest.h"
#include "sim/yaml/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  constexpr double kDuration = 2.0;
  try {
    const render::golden::RecordManifest m = render::golden::manifestText(text, "manifest.json", kDuration);
    const auto& c = m.times.checkpoints;
    for (size_t i = 0; i < c.size(); ++i)
      if (!(c[i] >= 0.0 && c[i] <= kDuration) || (i > 0 && !(c[i] > c[i - 1]))) std::abort();
    if (m.golden.width < 16 || m.golden.width > 8192 || m.golden.height < 16 || m.golden.height > 8192) std::abort();
    if (m.frameNames.size() != m.times.frames.size()) std::abort();
  } catch (const sim::yaml::SceneError&) {}
  return 0;
}

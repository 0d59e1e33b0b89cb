// libFuzzer target: the trace reader (`compare --trace`, `--overlay`, a golden record's trace.csv) on
// any bytes, against a scene of two bodies named as CSV makes hard ("a,b" and a quote). A
// SceneError is the expected answer to bad input; anything else (a crash, a sanitizer report,
// another exception) is a bug. What it reads must hold: each body's rows in time order, finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "render/trace/trace_csv.h"
#include "sim/yaml/scene_error.h"
#include "sim/yaml/scene_yaml.h"

namespace {

const sim::scene::SceneDef& scene() {
  static const sim::scene::SceneDef def = sim::yaml::loadSceneText(R"(
name: fuzz
bodies:
  - {name: "a,b", shape: {circle: 0.5}}
  - {name: "say \"hi\"", shape: {circle: 0.5}, position: [3, 0]}
)",
                                                                   "fuzz.yaml");
  return def;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const render::trace::Trace trace = render::trace::traceText(text, "fuzz.csv", scene());
    for (const auto& samples : trace.bodies)
      for (size_t i = 0; i < samples.size(); ++i)
        if (!std::isfinite(samples[i].t) || !std::isfinite(samples[i].x) || (i > 0 && samples[i].t < samples[i - 1].t))
          std::abort();
  } catch (const sim::yaml::SceneError&) {}
  return 0;
}

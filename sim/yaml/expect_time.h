// An `expect` entry's time and whether it is `energy_never_rises`, read alike in 2D and 3D: that
// entry holds at every step (up to its `time`, the duration unless given) and stands alone, since
// it is checked over the run where the others are checked at one time.
#pragma once

#include <string>

#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

struct ExpectTime {
  double time = 0.0;
  bool energyNeverRises = false;
};

inline ExpectTime readExpectTime(const Reader& r, const YAML::Node& entry, double duration) {
  ExpectTime out;
  if (const YAML::Node rises = entry["energy_never_rises"]) {
    if (!r.boolean(rises, "energy_never_rises"))
      r.fail(rises, "'energy_never_rises: false' checks nothing; remove the entry, or write 'energy_never_rises: true'");
    for (const auto& kv : entry) {
      const std::string key = kv.first.Scalar();
      if (key != "energy_never_rises" && key != "time" && key != "tolerance" && key != "source")
        r.fail(kv.second,
               "'" + key + "' is checked at one time, and 'energy_never_rises' at every step: give each an entry of its own");
    }
    out.energyNeverRises = true;
    out.time = duration;
  }
  if (!out.energyNeverRises || entry["time"]) {
    const YAML::Node t = r.required(entry, "time", "an expect entry");
    out.time = r.finite(t, "time");
    r.checkTime(t, out.time, duration, "expect");
  }
  return out;
}

}  // namespace sim::yaml

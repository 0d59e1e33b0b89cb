// A scene's lists of entries, `forces:`, `events:` and `expect:`, read alike in 2D and 3D: each is
// optional, must be a list, and all together hold at most max_entries (size_limits.h).
#pragma once

#include <string>

#include "sim/yaml/size_limits.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

// the list under `key`, if the scene has one, each entry read by `readEntry(node)`; `entries` counts
// those of the lists before it, and the list that passes the limit is refused at its start
template <class ReadEntry>
void readEntryList(const Reader& r, const YAML::Node& root, const std::string& key, size_t& entries, const SizeLimits& limits,
                   ReadEntry readEntry) {
  if (const YAML::Node list = root[key]) {
    if (!list.IsSequence()) r.fail(list, "'" + key + "' must be a list, got " + describe(list));
    checkEntryCount(r, list, entries, limits);
    for (const YAML::Node& n : list) readEntry(n);
  }
}

}  // namespace sim::yaml

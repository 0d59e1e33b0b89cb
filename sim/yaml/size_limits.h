// Documented bounds on the size of a scene, each with its override in `sim:` (as max_steps): the
// bodies of a scene and the vertices of one polygon. A scene file may hold 16 MiB (kMaxSceneBytes),
// enough for hundreds of thousands of bodies; these stop a generated scene that is larger than
// meant before it is built and stepped, with the key that raises the bound.
#pragma once

#include <limits>
#include <sstream>

#include "sim/core/settings.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

struct SizeLimits {
  int maxBodies = sim::core::settings::kDefaultMaxBodies;      // sim: {max_bodies: N}
  int maxVertices = sim::core::settings::kDefaultMaxVertices;  // sim: {max_vertices: N}
  int maxEntries = sim::core::settings::kDefaultMaxEntries;    // sim: {max_entries: N}
  int maxParts = sim::core::settings::kDefaultMaxParts;        // sim: {max_parts: N}
};

// the overrides in the scene's `sim:` map
inline void readSizeLimits(const Reader& r, const YAML::Node& sim, SizeLimits& limits) {
  constexpr int most = std::numeric_limits<int>::max();
  if (sim["max_bodies"]) limits.maxBodies = r.wholeNumber(sim["max_bodies"], "max_bodies", 1, most);
  if (sim["max_vertices"]) limits.maxVertices = r.wholeNumber(sim["max_vertices"], "max_vertices", 3, most);
  if (sim["max_entries"]) limits.maxEntries = r.wholeNumber(sim["max_entries"], "max_entries", 1, most);
  if (sim["max_parts"]) limits.maxParts = r.wholeNumber(sim["max_parts"], "max_parts", 2, most);
}

// the list `list` holds at most `limit` entries, else "<what> N <entries>, more than the limit of
// M; <advice>raise the limit with 'sim: {<key>: N}'" at the list
inline void checkCount(const Reader& r, const YAML::Node& list, int limit, const std::string& what, const std::string& entries,
                       const std::string& key, const std::string& advice) {
  if (list.size() <= static_cast<size_t>(limit)) return;
  std::ostringstream m;
  m << what << list.size() << " " << entries << ", more than the limit of " << limit << "; " << advice
    << "raise the limit with 'sim: {" << key << ": N}'";
  r.fail(list, m.str());
}

// the list `bodies` holds at most limits.maxBodies bodies
inline void checkBodyCount(const Reader& r, const YAML::Node& bodies, const SizeLimits& limits) {
  checkCount(r, bodies, limits.maxBodies, "the scene has ", "bodies", "max_bodies", "if it needs that many, ");
}

// the list `polygon` holds at most limits.maxVertices vertices
inline void checkVertexCount(const Reader& r, const YAML::Node& polygon, const SizeLimits& limits) {
  checkCount(r, polygon, limits.maxVertices, "a polygon of ", "vertices", "max_vertices",
             "a round outline needs far fewer (or is a circle), or ");
}

// the list `compound` holds at most limits.maxParts parts
inline void checkPartCount(const Reader& r, const YAML::Node& compound, const SizeLimits& limits) {
  checkCount(r, compound, limits.maxParts, "a body of ", "parts", "max_parts", "");
}

// forces, events and expect entries together hold at most limits.maxEntries: `seen` counts those
// of the lists before, and the list that passes the limit is refused at its start
inline void checkEntryCount(const Reader& r, const YAML::Node& list, size_t& seen, const SizeLimits& limits) {
  seen += list.size();
  if (seen <= static_cast<size_t>(limits.maxEntries)) return;
  std::ostringstream m;
  m << "forces, events and expect entries number " << seen << " up to this list, more than the limit of " << limits.maxEntries
    << "; if the scene needs that many, raise the limit with 'sim: {max_entries: N}'";
  r.fail(list, m.str());
}

}  // namespace sim::yaml

// What the 2D and the 3D reader of a scene's model read alike, on the dimension's reader (`Base`:
// sim::yaml::Reader, or sim::yaml3d::Reader3d with its vec3): the heading, the world block, the
// bound on steps, the list of bodies and their unique names, restitution, and the forces, events and
// expect entries, counted together toward max_entries. Each reader reads its own keys around these.
#pragma once

#include <string>
#include <unordered_set>

#include "sim/core/step_limit.h"
#include "sim/yaml/entry_list.h"
#include "sim/yaml/expect_entry.h"
#include "sim/yaml/force_reader.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/scene_yaml.h"
#include "sim/yaml/size_limits.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

template <class Base>
class ModelReaderOf : public Base {
 public:
  // `others`: the keys other layers read from the same maps, accepted and left alone
  ModelReaderOf(const SceneSource& source, const OtherKeys& others) : Base(source.file), others_(others) {
    this->placeUnmarked(source.variantMark);
  }

 protected:
  // the variant, name, description and duration; the name names output files, so it must make a path
  template <class Scene>
  void readHeading(const YAML::Node& root, const SceneSource& source, Scene& s) const {
    s.variant = source.variant;
    s.variantNames = source.variantNames;
    s.name = root["name"] ? this->text(root["name"], "name") : source.stem;
    if (const std::string fault = pathNameFault(s.name); !fault.empty())
      this->fail(root["name"] ? root["name"] : root, "the scene's name '" + shownName(s.name) + "' names its output files but " +
                                                         fault + "; give 'name:' letters, digits, '-' or '_'");
    this->optional(root, "description", s.description, &Reader::text);
    this->optional(root, "duration", s.duration, &Reader::positive);
  }

  // world: gravity, read by `vector` (&Reader::vec2 or &Reader3d::vec3), and the default restitution
  // and friction
  template <class Scene, class ReadVector>
  void readWorld(const YAML::Node& w, Scene& s, ReadVector vector) const {
    this->checkKeys(w, {"gravity", "restitution", "friction"}, "world");
    this->optional(w, "gravity", s.gravity, vector);
    if (w["restitution"]) s.restitution = restitution(w["restitution"]);
    this->optional(w, "friction", s.friction, &Reader::nonNegative);
  }

  // the run's steps, refused where they are set (dt, else duration, else the scene) when dt exceeds
  // the duration or the steps exceed max_steps; returns where they are set
  template <class Scene>
  YAML::Node checkStepCount(const YAML::Node& root, const Scene& s) const {
    const YAML::Node at = root["sim"] && root["sim"]["dt"] ? root["sim"]["dt"] : root["duration"] ? root["duration"] : root;
    if (const std::string over = sim::core::dtOverDuration(s.dt, s.duration); !over.empty())
      this->fail(at, over + "; choose a dt of at most the duration (a hundredth of it or less to see any motion)");
    if (const std::string over = sim::core::stepsOverLimit(s.dt, s.maxSteps, s.duration); !over.empty())
      this->fail(at, over +
                         "; raise dt, shorten duration, or, if the scene needs that many, raise the limit with "
                         "'sim: {max_steps: N}'");
    return at;
  }

  // bodies: a list of at least one, within max_bodies
  YAML::Node bodyList(const YAML::Node& root) const {
    const YAML::Node bodies = this->required(root, "bodies", "a scene");
    if (!bodies.IsSequence() || bodies.size() == 0) this->fail(bodies, "'bodies' must be a list of at least one body");
    checkBodyCount(*this, bodies, limits_);
    return bodies;
  }

  // a body's name, unique among the scene's bodies (and 3D's planes)
  std::string uniqueName(const YAML::Node& n) {
    std::string name = this->text(this->required(n, "name", "every body"), "name");
    if (name.empty()) this->fail(n, "a body's name cannot be empty");
    // by hash: a scan of the names before would make loading quadratic in the bodies
    if (!bodyNames_.insert(name).second) this->fail(n["name"], "duplicate body name '" + name + "'; names must be unique");
    return name;
  }

  double restitution(const YAML::Node& n) const {
    const double c = this->number(n, "restitution");
    if (!(c >= 0.0 && c <= 1.0)) this->fail(n, "'restitution' must be within [0, 1] (0: plastic, 1: elastic), got " + n.Scalar());
    return c;
  }

  // the forces, events and expect entries, which count together toward max_entries: forces and
  // events read alike but for `vector` (as readWorld's), each expect entry by `readExpect(node)`
  template <class Scene, class ReadVector, class ReadExpect>
  void readEntryLists(const YAML::Node& root, Scene& s, ReadVector vector, ReadExpect readExpect) const {
    const auto readVector = [this, vector](const YAML::Node& v, const std::string& key) { return (this->*vector)(v, key); };
    size_t entries = 0;
    readEntryList(*this, root, "forces", entries, limits_, [&](const YAML::Node& f) { readForce(*this, f, s, readVector); });
    readEntryList(*this, root, "events", entries, limits_,
                  [&](const YAML::Node& e) { s.events.push_back(readEvent(*this, e, s, readVector)); });
    readEntryList(*this, root, "expect", entries, limits_, [&](const YAML::Node& e) { s.expects.push_back(readExpect(e)); });
  }

  const OtherKeys& others_;
  SizeLimits limits_;

 private:
  std::unordered_set<std::string> bodyNames_;
};

}  // namespace sim::yaml

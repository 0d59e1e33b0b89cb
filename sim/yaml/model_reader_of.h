// What the 2D and the 3D reader of a scene's model read alike, on the dimension's reader (`Base`:
// sim::yaml::Reader, or sim::yaml3d::Reader3d with its vec3): the scene's outline in the order its
// faults are found (read()), the heading, the world block, the solver's iterations, the bound on
// steps, the list of bodies and their unique names, restitution, and the forces, events and expect
// entries, counted together toward max_entries. `Self`, the dimension's reader (a CRTP), reads what
// is its own: its dimension's check, its sim block, its bodies and its expect entries.
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

// `Scene`: the model read; Self has checkDimensions(root, dimensions), readSim(sim, scene),
// readBodies(list, scene) and readExpect(entry, scene), which read() calls
template <class Base, class Self, class Scene>
class ModelReaderOf : public Base {
 public:
  // `others`: the keys other layers read from the same maps, accepted and left alone
  ModelReaderOf(const SceneSource& source, const OtherKeys& others) : Base(source.file), others_(others) {
    this->placeUnmarked(source.variantMark);
  }

  // the scene's model, read in the order its faults are reported: the scene's keys, its dimension,
  // heading, world and sim, the bound on steps, the bodies, and the forces, events and expect entries
  Scene read(const SceneSource& source) {
    Self& self = static_cast<Self&>(*this);
    const YAML::Node root = source.root;
    this->checkKeys(root,
                    with({"name", "description", "dimensions", "duration", "world", "sim", "bodies", "forces", "events",
                          "variants", "expect"},
                         others_.scene),
                    "the scene");
    self.checkDimensions(root, source.dimensions);
    Scene s;
    readHeading(root, source, s);
    if (const YAML::Node w = root["world"]) readWorld(w, s);
    if (const YAML::Node sim = root["sim"]) self.readSim(sim, s);
    // a bound on work: a typo in dt must not run for years, nor one that takes no step
    checkStepCount(root, s);
    self.readBodies(bodyList(root), s);
    readEntryLists(root, s, [&](const YAML::Node& e) { return self.readExpect(e, s); });
    return s;
  }

 protected:
  // the variant, name, description and duration; the name names output files, so it must make a path
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

  // world: gravity, read by the dimension's vector reader (Base::kVector: &Reader::vec2 or
  // &Reader3d::vec3), and the default restitution and friction
  void readWorld(const YAML::Node& w, Scene& s) const {
    this->checkKeys(w, {"gravity", "restitution", "friction"}, "world");
    this->optional(w, "gravity", s.gravity, Base::kVector);
    if (w["restitution"]) s.restitution = restitution(w["restitution"]);
    this->optional(w, "friction", s.friction, &Reader::nonNegative);
  }

  // the run's steps, refused where they are set (dt, else duration, else the scene) when dt exceeds
  // the duration or the steps exceed max_steps
  void checkStepCount(const YAML::Node& root, const Scene& s) const {
    const YAML::Node at = root["sim"] && root["sim"]["dt"] ? root["sim"]["dt"] : root["duration"] ? root["duration"] : root;
    if (const std::string over = sim::core::dtOverDuration(s.dt, s.duration); !over.empty())
      this->fail(at, over + "; choose a dt of at most the duration (a hundredth of it or less to see any motion)");
    if (const std::string over = sim::core::stepsOverLimit(s.dt, s.maxSteps, s.duration); !over.empty())
      this->fail(at, over +
                         "; raise dt, shorten duration, or, if the scene needs that many, raise the limit with "
                         "'sim: {max_steps: N}'");
  }

  // sim: the stack solver's iterations (`iterations` for velocities, `position_iterations`)
  void readIterations(const YAML::Node& sim, Scene& s) const {
    if (sim["iterations"]) s.velocityIterations = this->wholeNumber(sim["iterations"], "iterations", 1, 1000);
    if (sim["position_iterations"])
      s.positionIterations = this->wholeNumber(sim["position_iterations"], "position_iterations", 0, 1000);
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
  // events read alike but for their vectors (as readWorld's), each expect entry by `readExpect(node)`
  template <class ReadExpect>
  void readEntryLists(const YAML::Node& root, Scene& s, ReadExpect readExpect) const {
    const auto readVector = [this](const YAML::Node& v, const std::string& key) { return (this->*Base::kVector)(v, key); };
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

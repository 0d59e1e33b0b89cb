// A scene's forces and impulse events, read alike in 2D and 3D (sim/core/force_defs.h): the 2D and
// the 3D reader pass the dimension's vector reader, [x, y] or [x, y, z].
#pragma once

#include <string>
#include <type_traits>

#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

// one entry of `forces:` (a spring, a point force or a drag) appended to the scene's lists;
// `vector(node, key)` reads the dimension's vector
template <class Scene, class ReadVector>
void readForce(const Reader& r, const YAML::Node& n, Scene& s, ReadVector vector) {
  if (!n.IsMap()) r.fail(n, "expected a map for a force, got " + describe(n));
  auto optionalVector = [&](const char* key, auto& out) {
    if (const YAML::Node v = n[key]) out = vector(v, key);
  };
  // without a type, a misspelled key is the likelier fault: name it
  if (!n["type"])
    r.checkKeys(n,
                {"type", "body", "point", "anchor", "body2", "point2", "stiffness", "rest_length", "damping", "frame", "force",
                 "from", "until", "linear", "angular"},
                "a force");
  const std::string type = r.text(r.required(n, "type", "every force"), "type");
  if (type == "spring") {
    r.checkKeys(n, {"type", "body", "point", "anchor", "body2", "point2", "stiffness", "rest_length", "damping"}, "a spring");
    typename std::decay_t<decltype(s.springs)>::value_type sp;
    sp.body = r.bodyRef(n, "body", s, "a spring");
    optionalVector("point", sp.point);
    if (n["body2"]) {
      if (n["anchor"]) r.fail(n["anchor"], "a spring has either 'anchor' (a world point) or 'body2', not both");
      sp.body2 = r.bodyRef(n, "body2", s, "a spring");
      if (sp.body2 == sp.body) r.fail(n["body2"], "a spring needs two different bodies");
      optionalVector("point2", sp.point2);
    } else {
      if (n["point2"]) r.fail(n["point2"], "'point2' goes with 'body2'");
      sp.anchor = vector(r.required(n, "anchor", "a spring without 'body2'"), "anchor");
    }
    sp.stiffness = r.nonNegative(r.required(n, "stiffness", "a spring"), "stiffness");
    r.optional(n, "rest_length", sp.restLength, &Reader::nonNegative);
    r.optional(n, "damping", sp.damping, &Reader::nonNegative);
    s.springs.push_back(sp);
  } else if (type == "force") {
    r.checkKeys(n, {"type", "body", "point", "frame", "force", "from", "until"}, "a force");
    typename std::decay_t<decltype(s.pointForces)>::value_type f;
    f.body = r.bodyRef(n, "body", s, "a force");
    optionalVector("point", f.point);
    f.force = vector(r.required(n, "force", "a force"), "force");
    if (n["frame"]) f.bodyFrame = r.coordinateFrame(n["frame"]) == "body";
    r.optional(n, "from", f.from, &Reader::nonNegative);
    if (n["until"]) {
      f.until = r.finite(n["until"], "until");
      if (!(f.until > f.from)) r.fail(n["until"], "'until' must come after 'from'");
    }
    s.pointForces.push_back(f);
  } else if (type == "drag") {
    r.checkKeys(n, {"type", "body", "linear", "angular"}, "a drag");
    typename std::decay_t<decltype(s.drags)>::value_type d;
    d.body = r.bodyRef(n, "body", s, "a drag");
    r.optional(n, "linear", d.linear, &Reader::nonNegative);
    r.optional(n, "angular", d.angular, &Reader::nonNegative);
    s.drags.push_back(d);
  } else {
    r.fail(n["type"], "unknown force type '" + type + "'; choose one of: spring, force, drag (gravity is set in world:)");
  }
}

// one entry of `events:`, an impulse on a body at a time within the scene's duration
template <class Scene, class ReadVector>
auto readEvent(const Reader& r, const YAML::Node& n, const Scene& s, ReadVector vector) {
  r.checkKeys(n, {"time", "body", "impulse", "point", "frame"}, "an event");
  typename std::decay_t<decltype(s.events)>::value_type e;
  const YAML::Node t = r.required(n, "time", "an event");
  e.time = r.finite(t, "time");
  r.checkTime(t, e.time, s.duration, "event");
  e.body = r.bodyRef(n, "body", s, "an event");
  e.impulse = vector(r.required(n, "impulse", "an event"), "impulse");
  if (const YAML::Node p = n["point"]) e.point = vector(p, "point");
  if (n["frame"]) e.pointInWorld = r.coordinateFrame(n["frame"]) == "world";
  return e;
}

}  // namespace sim::yaml

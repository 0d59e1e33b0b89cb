#include "sim/yaml/scene_yaml.h"

#include "sim/yaml/render_yaml.h"
#include "sim/yaml/yaml_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace sim::yaml {
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;

SceneError::SceneError(std::string f, int l, int c, const std::string& m)
    : std::runtime_error(l > 0 ? f + ":" + std::to_string(l) + ":" + std::to_string(c) + ": " + m : f + ": " + m),
      file(std::move(f)),
      line(l),
      column(c),
      message(m) {}

namespace {

using yaml::describe;
using yaml::Keys;
using yaml::Reader;

// base[key] = value, keeping the key's position in the file for messages about a new key
// (looked up through a const node: yaml-cpp's non-const operator[] adds an empty entry)
void setKey(YAML::Node base, const YAML::Node& key, const YAML::Node& value) {
  if (std::as_const(base)[key.Scalar()]) base[key.Scalar()] = value;
  else base.force_insert(key, value);
}

// variants are merged over the scene: maps key by key, the bodies list by name, other values whole
void mergeBodies(YAML::Node base, const YAML::Node& over) {
  for (const YAML::Node& body : over) {
    bool merged = false;
    if (body.IsMap() && body["name"]) {
      for (YAML::Node b : base)
        if (b.IsMap() && std::as_const(b)["name"] && std::as_const(b)["name"].Scalar() == body["name"].Scalar()) {
          for (const auto& kv : body) setKey(b, kv.first, kv.second);
          merged = true;
        }
    }
    if (!merged) base.push_back(body);
  }
}

void mergeMaps(YAML::Node base, const YAML::Node& over) {
  for (const auto& kv : over) {
    const std::string key = kv.first.Scalar();
    const YAML::Node current = std::as_const(base)[key];
    if (current && current.IsMap() && kv.second.IsMap()) {
      mergeMaps(current, kv.second);
    } else if (key == "bodies" && current && current.IsSequence() && kv.second.IsSequence()) {
      mergeBodies(current, kv.second);
    } else {
      setKey(base, kv.first, kv.second);
    }
  }
}

std::string joined(const std::vector<std::string_view>& names) {
  std::string s;
  for (auto n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

class SceneReader : public Reader {
 public:
  using Reader::Reader;

  SceneDef read(YAML::Node root, const std::string& defaultName, const std::string& variant) {
    if (!root.IsMap()) fail(root, "a scene is a map with at least 'bodies:'; got " + describe(root));
    SceneDef s;
    readVariants(root, s, variant);
    checkKeys(root, {"name", "description", "duration", "world", "sim", "bodies", "forces", "events", "variants", "expect", "render", "stability"},
              "the scene");
    s.name = root["name"] ? text(root["name"], "name") : defaultName;
    if (root["description"]) s.description = text(root["description"], "description");
    if (root["duration"]) s.duration = positive(root["duration"], "duration");
    if (const YAML::Node w = root["world"]) {
      checkKeys(w, {"gravity", "restitution", "friction"}, "world");
      if (w["gravity"]) s.gravity = vec2(w["gravity"], "gravity");
      if (w["restitution"]) s.restitution = restitution(w["restitution"]);
      if (w["friction"]) s.friction = nonNegative(w["friction"], "friction");
    }
    if (const YAML::Node sim = root["sim"]) {
      checkKeys(sim, {"integrator", "dt", "collisions", "iterations", "position_iterations"}, "sim");
      if (sim["collisions"])
        s.collisions = named(sim["collisions"], "collisions", collisionMethodFromName, joined(collisionMethodNames()));
      if (sim["iterations"]) s.velocityIterations = count(sim["iterations"], "iterations");
      if (sim["position_iterations"]) s.positionIterations = count(sim["position_iterations"], "position_iterations", 0);
      if (sim["integrator"])
        s.integrator = named(sim["integrator"], "integrator", integratorFromName, joined(integratorNames()));
      if (sim["dt"]) s.dt = positive(sim["dt"], "dt");
    }
    const YAML::Node bodies = required(root, "bodies", "a scene");
    if (!bodies.IsSequence() || bodies.size() == 0) fail(bodies, "'bodies' must be a list of at least one body");
    for (const YAML::Node& b : bodies) s.bodies.push_back(readBody(b, s));
    if (const YAML::Node forces = root["forces"]) {
      if (!forces.IsSequence()) fail(forces, "'forces' must be a list, got " + describe(forces));
      for (const YAML::Node& f : forces) readForce(f, s);
    }
    if (const YAML::Node events = root["events"]) {
      if (!events.IsSequence()) fail(events, "'events' must be a list, got " + describe(events));
      for (const YAML::Node& e : events) s.events.push_back(readEvent(e, s));
    }
    if (const YAML::Node expect = root["expect"]) {
      if (!expect.IsSequence()) fail(expect, "'expect' must be a list, got " + describe(expect));
      for (const YAML::Node& e : expect) s.expects.push_back(readExpect(e, s));
    }
    if (const YAML::Node r = root["render"]) {
      yaml::readRender(r, *this, s.render);
      yaml::readOverlays(r, *this, s, s.render.overlays);
    }
    const YAML::Node render = root["render"];
    yaml::readPanels(render ? render["panels"] : render, *this, s.duration, s.variantNames.size(), s.render.panels);
    if (const YAML::Node st = root["stability"]) s.stability = readStability(st, s);
    return s;
  }

 private:
  void readVariants(YAML::Node root, SceneDef& s, const std::string& variant) {
    const YAML::Node variants = root["variants"];
    if (variants) {
      if (!variants.IsMap()) fail(variants, "'variants' must be a map from names to changes, got " + describe(variants));
      for (const auto& kv : variants) {
        if (!kv.second.IsMap() && !kv.second.IsNull())
          fail(kv.second, "variant '" + kv.first.Scalar() + "' must be a map of changes, got " + describe(kv.second));
        s.variantNames.push_back(kv.first.Scalar());
      }
    }
    if (variant.empty()) return;
    if (std::find(s.variantNames.begin(), s.variantNames.end(), variant) == s.variantNames.end()) {
      std::string known;
      for (const auto& n : s.variantNames) known += (known.empty() ? "" : ", ") + n;
      fail(variants ? variants : root, "unknown variant '" + variant + "'; " +
                                           (known.empty() ? "this scene has no variants" : "this scene has: " + known));
    }
    const YAML::Node changes = variants[variant];
    if (changes.IsMap()) {
      if (changes["variants"]) fail(changes["variants"], "a variant cannot define variants");
      mergeMaps(root, changes);
    }
    s.variant = variant;
  }

  Shape readShape(const YAML::Node& n) {
    checkKeys(n, {"box", "polygon", "circle", "plane"}, "shape");
    if (n.size() != 1)
      fail(n, "a shape is exactly one of {box: [w, h]}, {polygon: [[x, y], ...]}, {circle: r}, {plane: {point, normal}}");
    try {
      if (const YAML::Node box = n["box"]) {
        const Vec2 size = vec2(box, "box");
        if (!(size.x() > 0.0) || !(size.y() > 0.0)) fail(box, "box width and height must be positive");
        return makeBox(size.x(), size.y());
      }
      if (const YAML::Node circle = n["circle"]) return makeCircle(positive(circle, "circle"));
      if (const YAML::Node plane = n["plane"]) {
        checkKeys(plane, {"point", "normal"}, "plane");
        const YAML::Node normal = required(plane, "normal", "a plane");
        try {
          return makePlane(vec2(normal, "normal"));
        } catch (const std::invalid_argument& e) {
          fail(normal, e.what());
        }
      }
      const YAML::Node poly = n["polygon"];
      if (!poly.IsSequence()) fail(poly, "expected a list of [x, y] vertices for 'polygon', got " + describe(poly));
      std::vector<Vec2> vertices;
      for (const YAML::Node& v : poly) vertices.push_back(vec2(v, "polygon vertex"));
      return makePolygon(std::move(vertices));
    } catch (const std::invalid_argument& e) {
      fail(n, e.what());
    }
  }

  BodyDef readBody(const YAML::Node& n, const SceneDef& s) {
    checkKeys(n, {"name", "shape", "density", "mass", "inertia", "position", "angle", "velocity", "angular_velocity",
                  "static", "color", "label", "restitution", "friction"},
              "a body");
    BodyDef b;
    b.loc = {n.Mark().line + 1, n.Mark().column + 1};
    b.name = text(required(n, "name", "every body"), "name");
    if (b.name.empty()) fail(n, "a body's name cannot be empty");
    if (s.bodyIndex(b.name) >= 0) fail(n["name"], "duplicate body name '" + b.name + "'; names must be unique");
    b.shape = readShape(required(n, "shape", "body '" + b.name + "'"));
    if (n["density"]) b.density = positive(n["density"], "density");
    if (n["mass"]) b.mass = positive(n["mass"], "mass");
    if (n["inertia"]) b.inertia = positive(n["inertia"], "inertia");
    if (n["position"]) b.position = vec2(n["position"], "position");
    if (n["angle"]) b.angle = finite(n["angle"], "angle");
    if (n["velocity"]) b.velocity = vec2(n["velocity"], "velocity");
    if (n["angular_velocity"]) b.angularVelocity = finite(n["angular_velocity"], "angular_velocity");
    if (n["static"]) b.isStatic = boolean(n["static"], "static");
    if (n["restitution"]) b.restitution = restitution(n["restitution"]);
    if (n["friction"]) b.friction = nonNegative(n["friction"], "friction");
    if (b.shape.kind == ShapeKind::Plane) {
      // a half-plane is an obstacle: static, placed by its point
      if (n["static"] && !b.isStatic) fail(n["static"], "a plane is always static");
      for (const char* key : {"position", "angle", "density", "mass", "inertia"})
        if (n[key]) fail(n[key], std::string("a plane has no '") + key + "'; place it with its 'point' and 'normal'");
      b.isStatic = true;
      const YAML::Node plane = n["shape"]["plane"];
      if (plane["point"]) b.position = vec2(plane["point"], "point");
    }
    if (b.isStatic && (b.velocity != Vec2::Zero() || b.angularVelocity != 0.0))
      fail(n, "static body '" + b.name + "' cannot move; remove its velocity or make it dynamic");
    if (n["color"]) {
      b.color = text(n["color"], "color");
      const bool hex = b.color.size() == 7 && b.color[0] == '#' &&
                       std::all_of(b.color.begin() + 1, b.color.end(), [](char c) { return std::isxdigit(c); });
      if (!hex) fail(n["color"], "color must be written \"#rrggbb\", got '" + b.color + "'");
    }
    b.label = n["label"] ? text(n["label"], "label") : b.name;
    return b;
  }

  std::string bodyRef(const YAML::Node& map, const std::string& key, const SceneDef& s, const std::string& what) {
    const YAML::Node n = required(map, key, what);
    const std::string name = text(n, key);
    if (s.bodyIndex(name) < 0) fail(n, "no body named '" + name + "'" + knownBodies(s));
    return name;
  }

  static std::string knownBodies(const SceneDef& s) {
    std::string known;
    for (const BodyDef& b : s.bodies) known += (known.empty() ? "; the bodies are: " : ", ") + b.name;
    return known;
  }

  void readForce(const YAML::Node& n, SceneDef& s) {
    if (!n.IsMap()) fail(n, "expected a map for a force, got " + describe(n));
    // without a type, a misspelled key is the likelier fault: name it
    if (!n["type"])
      checkKeys(n, {"type", "body", "point", "anchor", "body2", "point2", "stiffness", "rest_length", "damping", "frame",
                    "force", "from", "until", "linear", "angular"},
                "a force");
    const std::string type = text(required(n, "type", "every force"), "type");
    if (type == "spring") {
      checkKeys(n, {"type", "body", "point", "anchor", "body2", "point2", "stiffness", "rest_length", "damping"}, "a spring");
      SpringDef sp;
      sp.body = bodyRef(n, "body", s, "a spring");
      if (n["point"]) sp.point = vec2(n["point"], "point");
      if (n["body2"]) {
        if (n["anchor"]) fail(n["anchor"], "a spring has either 'anchor' (a world point) or 'body2', not both");
        sp.body2 = bodyRef(n, "body2", s, "a spring");
        if (sp.body2 == sp.body) fail(n["body2"], "a spring needs two different bodies");
        if (n["point2"]) sp.point2 = vec2(n["point2"], "point2");
      } else {
        if (n["point2"]) fail(n["point2"], "'point2' goes with 'body2'");
        sp.anchor = vec2(required(n, "anchor", "a spring without 'body2'"), "anchor");
      }
      sp.stiffness = nonNegative(required(n, "stiffness", "a spring"), "stiffness");
      if (n["rest_length"]) sp.restLength = nonNegative(n["rest_length"], "rest_length");
      if (n["damping"]) sp.damping = nonNegative(n["damping"], "damping");
      s.springs.push_back(sp);
    } else if (type == "force") {
      checkKeys(n, {"type", "body", "point", "frame", "force", "from", "until"}, "a force");
      PointForceDef f;
      f.body = bodyRef(n, "body", s, "a force");
      if (n["point"]) f.point = vec2(n["point"], "point");
      f.force = vec2(required(n, "force", "a force"), "force");
      if (n["frame"]) f.bodyFrame = frame(n["frame"]) == "body";
      if (n["from"]) f.from = nonNegative(n["from"], "from");
      if (n["until"]) {
        f.until = finite(n["until"], "until");
        if (!(f.until > f.from)) fail(n["until"], "'until' must come after 'from'");
      }
      s.pointForces.push_back(f);
    } else if (type == "drag") {
      checkKeys(n, {"type", "body", "linear", "angular"}, "a drag");
      DragDef d;
      d.body = bodyRef(n, "body", s, "a drag");
      if (n["linear"]) d.linear = nonNegative(n["linear"], "linear");
      if (n["angular"]) d.angular = nonNegative(n["angular"], "angular");
      s.drags.push_back(d);
    } else {
      fail(n["type"], "unknown force type '" + type + "'; choose one of: spring, force, drag (gravity is set in world:)");
    }
  }

  double restitution(const YAML::Node& n) {
    const double c = number(n, "restitution");
    if (!(c >= 0.0 && c <= 1.0)) fail(n, "'restitution' must be within [0, 1] (0: plastic, 1: elastic), got " + n.Scalar());
    return c;
  }

  int count(const YAML::Node& n, const std::string& key, int least = 1) {
    const double x = number(n, key);
    if (x != std::floor(x) || x < least || x > 1000)
      fail(n, "'" + key + "' must be a whole number from " + std::to_string(least) + " to 1000, got " + n.Scalar());
    return static_cast<int>(x);
  }

  StabilityDef readStability(const YAML::Node& n, const SceneDef& s) {
    checkKeys(n, {"parameter", "body", "from", "to", "stack"}, "stability");
    StabilityDef d;
    if (n["parameter"]) {
      const std::string p = text(n["parameter"], "parameter");
      if (p == "dt") d.parameter = StabilityDef::Parameter::Dt;
      else if (p == "speed") d.parameter = StabilityDef::Parameter::Speed;
      else if (p == "mass_ratio") d.parameter = StabilityDef::Parameter::MassRatio;
      else if (p == "stack_height") d.parameter = StabilityDef::Parameter::StackHeight;
      else fail(n["parameter"], "unknown stability parameter '" + p + "'; choose one of: dt, speed, mass_ratio, stack_height");
    }
    const bool needsBody = d.parameter == StabilityDef::Parameter::Speed || d.parameter == StabilityDef::Parameter::MassRatio;
    if (needsBody) d.body = bodyRef(n, "body", s, "stability with this parameter");
    else if (n["body"]) fail(n["body"], "'body' goes with the parameters speed and mass_ratio");
    if (n["from"]) d.from = positive(n["from"], "from");
    if (n["to"]) d.to = positive(n["to"], "to");
    if (d.to > 0.0 && d.from > 0.0 && !(d.to > d.from)) fail(n["to"], "'to' must be larger than 'from'");
    if (n["stack"]) d.stack = boolean(n["stack"], "stack");
    if (d.parameter == StabilityDef::Parameter::StackHeight) d.stack = true;
    return d;
  }

  std::string frame(const YAML::Node& n) {
    const std::string f = text(n, "frame");
    if (f != "body" && f != "world") fail(n, "frame must be 'body' or 'world', got '" + f + "'");
    return f;
  }

  void checkTime(const YAML::Node& n, double t, const SceneDef& s, const std::string& what) {
    if (t < 0.0 || t > s.duration)
      fail(n, what + " time " + n.Scalar() + " is outside the scene's duration [0, " + formatNumber(s.duration) +
                  "]; move it or lengthen 'duration'");
  }

  static std::string formatNumber(double x) {
    std::ostringstream o;
    o << x;
    return o.str();
  }

  EventDef readEvent(const YAML::Node& n, const SceneDef& s) {
    checkKeys(n, {"time", "body", "impulse", "point", "frame"}, "an event");
    EventDef e;
    const YAML::Node t = required(n, "time", "an event");
    e.time = finite(t, "time");
    checkTime(t, e.time, s, "event");
    e.body = bodyRef(n, "body", s, "an event");
    e.impulse = vec2(required(n, "impulse", "an event"), "impulse");
    if (n["point"]) e.point = vec2(n["point"], "point");
    if (n["frame"]) e.pointInWorld = frame(n["frame"]) == "world";
    return e;
  }

  ExpectDef readExpect(const YAML::Node& n, const SceneDef& s) {
    checkKeys(n, {"time", "body", "position", "angle", "velocity", "angular_velocity", "kinetic_energy",
                  "potential_energy", "total_energy", "momentum", "angular_momentum", "tolerance"},
              "an expect entry");
    ExpectDef e;
    e.loc = {n.Mark().line + 1, n.Mark().column + 1};
    const YAML::Node t = required(n, "time", "an expect entry");
    e.time = finite(t, "time");
    checkTime(t, e.time, s, "expect");
    if (n["body"]) e.body = bodyRef(n, "body", s, "an expect entry");
    for (const char* key : {"position", "angle", "velocity", "angular_velocity"})
      if (n[key] && e.body.empty()) fail(n[key], std::string("'") + key + "' is a body's: add 'body:'");
    if (n["position"]) e.position = vec2(n["position"], "position");
    if (n["angle"]) e.angle = finite(n["angle"], "angle");
    if (n["velocity"]) e.velocity = vec2(n["velocity"], "velocity");
    if (n["angular_velocity"]) e.angularVelocity = finite(n["angular_velocity"], "angular_velocity");
    if (n["kinetic_energy"]) e.kineticEnergy = finite(n["kinetic_energy"], "kinetic_energy");
    if (n["potential_energy"]) e.potentialEnergy = finite(n["potential_energy"], "potential_energy");
    if (n["total_energy"]) e.totalEnergy = finite(n["total_energy"], "total_energy");
    if (n["momentum"]) e.momentum = vec2(n["momentum"], "momentum");
    if (n["angular_momentum"]) e.angularMomentum = finite(n["angular_momentum"], "angular_momentum");
    if (n["tolerance"]) e.tolerance = positive(n["tolerance"], "tolerance");
    return e;
  }
};

std::string stem(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  if (base.size() > 5 && base.ends_with(".yaml")) base.resize(base.size() - 5);
  else if (base.size() > 4 && base.ends_with(".yml")) base.resize(base.size() - 4);
  return base;
}

}  // namespace

SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, "invalid YAML: " + e.msg);
  }
  if (!root || root.IsNull()) throw SceneError(file, 1, 1, "the scene is empty; it needs at least 'bodies:'");
  try {
    return SceneReader(file).read(root, stem(file), variant);
  } catch (const YAML::Exception& e) {
    // a tree shape the reader did not foresee: still a message with a position, not a crash
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
}

SceneDef loadSceneFile(const std::string& path, const std::string& variant) {
  if (std::filesystem::is_directory(path))
    throw SceneError(path, 0, 0, "is a directory, not a scene file; give the path of a .yaml file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, 0, 0, "cannot open the scene file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  return loadSceneText(text.str(), path, variant);
}

}  // namespace sim::yaml

#include "sim/yaml3d/scene_yaml.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "sim/scene3d/contact_pairs.h"
#include "sim/scene3d/scene_build.h"
#include "sim/yaml/expect_entry.h"
#include "sim/yaml/model_reader_of.h"
#include "sim/yaml/size_limits.h"
#include "sim/world3d/method_models3d.h"
#include "sim/yaml3d/reader3d.h"

namespace sim::yaml3d {
using sim::world3d::Quat;
using namespace sim::yaml;
using namespace sim::scene3d;
using namespace sim::world3d;
using sim::world3d::Shape;

namespace {

// keys of a 2D scene that 3D has no use for, and why: said instead of "unknown key"
using Refusals = std::vector<std::pair<const char*, std::string>>;
const Refusals kSimRefusals = {{"max_vertices", "3D shapes have no vertices to bound ('max_vertices' bounds a 2D polygon's)"},
                               {"substeps", "3D has no soft_step, so no 'substeps'"},
                               {"contact_hertz", "3D has no soft_step, so no 'contact_hertz'"},
                               {"precision", "3D has no soft_step, so no 'precision'"},
                               {"sleep", "3D piles do not sleep: 'sleep' is 2D's"},
                               {"threads", "3D's solver runs on one thread: 'threads' is 2D's"}};
const Refusals kBodyRefusals = {
    {"angle", "a 3D body turns by 'orientation': a unit quaternion [w, x, y, z] or {axis: [x, y, z], angle: θ}"},
    {"static", "3D has no static bodies: an obstacle is a plane, {plane: {point: [x, y, z], normal: [nx, ny, nz]}}"}};
const Refusals kShapeRefusals = {
    {"circle", "'circle' is a 2D shape; in 3D a shape is {box: [a, b, c]}, {sphere: r} or {ellipsoid: [a, b, c]}"},
    {"polygon", "'polygon' is a 2D shape; in 3D a shape is {box: [a, b, c]}, {sphere: r} or {ellipsoid: [a, b, c]}"}};
const Refusals kExpectRefusals = {{"angle", "a 3D body's rotation is checked by 'orientation': [w, x, y, z]"}};

class SceneReader3d : public ModelReaderOf<Reader3d, SceneReader3d, SceneDef> {
 public:
  using ModelReaderOf::ModelReaderOf;

  void checkDimensions(const YAML::Node& root, int dimensions) const {
    if (dimensions != 3) fail(root, "this reads 3D scenes, which say 'dimensions: 3'");
  }

  // the bodies, and the obstacles among them: {plane: {point, normal}} is a static half-space
  void readBodies(const YAML::Node& list, SceneDef& s) {
    for (const YAML::Node& b : list) {
      if (b.IsMap() && b["shape"] && b["shape"].IsMap() && b["shape"]["plane"]) s.planes.push_back(readPlane(b));
      else s.bodies.push_back(readBody(b));
    }
    if (s.bodies.empty()) fail(list, "a scene needs at least one body that moves; planes are obstacles only");
    checkPairs(list, s);
  }

  // sim: the method and its iterations, the integrator, dt and normalize; a 2D option is refused
  // with why 3D has none
  void readSim(const YAML::Node& sim, SceneDef& s) {
    keys(sim,
         {"integrator", "dt", "normalize", "collisions", "iterations", "position_iterations", "max_steps", "max_bodies",
          "max_entries"},
         kSimRefusals, "sim");
    if (const YAML::Node c = sim["collisions"]) {
      s.collisions = named(c, "collisions", sim::core::collisionMethodFromName, sim::core::kCollisionMethodNames.list());
      if (!sim::world3d::methodModel3d(s.collisions) && s.collisions != sim::core::CollisionMethod::Auto)
        fail(c, "'" + c.Scalar() + "' is a 2D method; 3D scenes take 'auto', 'none', 'event' or 'sequential'");
      s.collisionsLoc = place(c);
    }
    readIterations(sim, s);
    optional(sim, "max_steps", s.maxSteps, &Reader::positive);
    readSizeLimits(*this, sim, limits_);
    if (sim["integrator"])
      s.integrator = named(
          sim["integrator"], "integrator", [](const std::string& n) { return kIntegratorNames.parse(n); },
          kIntegratorNames.list());
    optional(sim, "dt", s.dt, &Reader::positive);
    optional(sim, "normalize", s.normalize, &Reader::boolean);
  }

  // every key of `map` one of `allowed`; a 2D key among `refused` fails with its reason
  void keys(const YAML::Node& map, const Keys& allowed, const Refusals& refused, const std::string& what) const {
    if (map.IsMap())
      for (const auto& [key, reason] : refused)
        if (const YAML::Node n = map[key]) fail(n, reason);
    checkKeys(map, allowed, what);
  }

  Shape readShape(const YAML::Node& n) {
    if (n.IsMap())
      for (const auto& [key, reason] : kShapeRefusals)
        if (n[key]) fail(n, reason);
    checkKeys(n, {"box", "sphere", "ellipsoid", "plane"}, "shape");
    if (n.size() != 1)
      fail(n, "a shape is exactly one of {box: [a, b, c]} (sides), {sphere: r}, {ellipsoid: [a, b, c]} (semi-axes)");
    try {
      if (const YAML::Node box = n["box"]) return makeBox(vec3(box, "box"));
      if (const YAML::Node sphere = n["sphere"]) return makeSphere(positive(sphere, "sphere"));
      return makeEllipsoid(vec3(n["ellipsoid"], "ellipsoid"));
    } catch (const std::invalid_argument& e) {
      fail(n, e.what());
    }
  }

  PlaneDef readPlane(const YAML::Node& n) {
    for (const char* key : {"density", "mass", "inertia", "position", "orientation", "velocity", "angular_velocity"})
      if (n[key]) fail(n[key], std::string("a plane has no '") + key + "'; place it with its 'point' and 'normal'");
    keys(n, with({"name", "shape", "restitution", "friction"}, others_.body), kBodyRefusals, "a plane");
    PlaneDef p;
    p.loc = place(n);
    p.name = uniqueName(n);
    const YAML::Node shape = n["shape"];
    if (shape.size() != 1) fail(shape, "a shape is exactly one of {box}, {sphere}, {ellipsoid} or {plane: {point, normal}}");
    const YAML::Node plane = shape["plane"];
    checkKeys(plane, {"point", "normal"}, "plane");
    optional(plane, "point", p.point, &Reader3d::vec3);
    const YAML::Node normal = required(plane, "normal", "a plane");
    p.normal = vec3(normal, "normal");
    // scaled by its largest component first, so that [1e200, 0, 0] or [1e-160, 0, 0] come out unit
    const double largest = p.normal.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) fail(normal, "a plane's normal must not be zero; give the direction out of the solid, e.g. [0, 0, 1]");
    p.normal = (p.normal / largest).normalized();
    if (n["restitution"]) p.restitution = restitution(n["restitution"]);
    optional(n, "friction", p.friction, &Reader::nonNegative);
    return p;
  }

  // a body pair without a contact model, in a scene whose contacts act on bodies: refused at the
  // second body rather than let pass through
  void checkPairs(const YAML::Node& nodes, const SceneDef& s) {
    const auto pair = unmodeledPair(s);
    if (!pair) return;
    const BodyDef &b = s.bodies[pair->second], &other = s.bodies[pair->first];
    for (const YAML::Node& n : nodes)
      if (n.IsMap() && n["name"] && n["name"].Scalar() == b.name) fail(n, unmodeledPairMessage(other.name, b.name));
  }

  BodyDef readBody(const YAML::Node& n) {
    if (!n.IsMap()) fail(n, "expected a map for a body, got " + describe(n));
    keys(n,
         with({"name", "shape", "density", "mass", "inertia", "position", "orientation", "velocity", "angular_velocity",
               "restitution", "friction"},
              others_.body),
         kBodyRefusals, "a body");
    BodyDef b;
    b.loc = b.massLoc = {n.Mark().line + 1, n.Mark().column + 1};
    b.name = uniqueName(n);
    b.shape = readShape(required(n, "shape", "body '" + b.name + "'"));
    if (n["restitution"]) b.restitution = restitution(n["restitution"]);
    optional(n, "friction", b.friction, &Reader::nonNegative);
    optional(n, "density", b.density, &Reader::positive);
    optional(n, "mass", b.mass, &Reader::positive);
    if (const YAML::Node i = n["inertia"]) b.inertia = inertia(i, "inertia");
    optional(n, "position", b.position, &Reader3d::vec3);
    optional(n, "orientation", b.orientation, &Reader3d::orientation);
    optional(n, "velocity", b.velocity, &Reader3d::vec3);
    optional(n, "angular_velocity", b.angularVelocity, &Reader3d::vec3);
    // a tensor that no solid has (not symmetric, a moment not positive, I1 + I2 < I3) is located here
    try {
      (void)buildBody(b);
    } catch (const std::invalid_argument& e) {
      fail(n["inertia"] ? n["inertia"] : n["mass"] ? n["mass"] : n, std::string(e.what()));
    }
    return b;
  }

  ExpectDef readExpect(const YAML::Node& n, const SceneDef& s) {
    if (!n.IsMap()) fail(n, "expected a map for an expect entry, got " + describe(n));
    keys(n,
         {"time", "body", "position", "orientation", "velocity", "angular_velocity", "quaternion_norm", "kinetic_energy",
          "potential_energy", "total_energy", "momentum", "angular_momentum", "cone_angle", "precession_rate",
          "space_precession_rate", "flip_period", "energy_never_rises", "tolerance", "source"},
         kExpectRefusals, "an expect entry");
    ExpectDef e;
    readExpectHead(*this, n, s,
                   {"position", "orientation", "velocity", "angular_velocity", "quaternion_norm", "cone_angle", "precession_rate",
                    "space_precession_rate", "flip_period"},
                   e);
    optional(n, "position", e.position, &Reader3d::vec3);
    // typed as the scene's orientation is, but as an answer: a quaternion is compared as written
    if (const YAML::Node q = n["orientation"]) {
      if (!q.IsSequence() || q.size() != 4) fail(q, "expected [w, x, y, z] for 'orientation'");
      e.orientation = Quat(finite(q[0], "orientation"), finite(q[1], "orientation"), finite(q[2], "orientation"),
                           finite(q[3], "orientation"));
    }
    optional(n, "velocity", e.velocity, &Reader3d::vec3);
    optional(n, "angular_velocity", e.angularVelocity, &Reader3d::vec3);
    optional(n, "quaternion_norm", e.quaternionNorm, &Reader::positive);
    readExpectMomenta(*this, n, e, &Reader3d::vec3);
    readTopAnswers(n, e);
    readExpectTolerance(*this, n, e);
    return e;
  }

  // the free body's closed forms (sim/scene3d/scene_def.h): the angle between ω and L, the rates of
  // ω about the symmetry axis in the body and of that axis about L in space, and ω's flip period
  void readTopAnswers(const YAML::Node& n, ExpectDef& e) const {
    optional(n, "cone_angle", e.coneAngle, &Reader::nonNegative);
    optional(n, "precession_rate", e.precessionRate, &Reader::finite);
    optional(n, "space_precession_rate", e.spacePrecessionRate, &Reader::finite);
    optional(n, "flip_period", e.flipPeriod, &Reader::positive);
  }
};

}  // namespace

SceneDef readModel(const SceneSource& source, const OtherKeys& others) {
  return sim::yaml::readGuarded(source.file, [&] { return SceneReader3d(source, others).read(source); });
}

SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant) {
  return sim::yaml3d::readModel(sim::yaml::sceneSourceText(text, file, variant));
}

}  // namespace sim::yaml3d

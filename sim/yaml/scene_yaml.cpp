#include "sim/yaml/scene_yaml.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/collision/compound.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/expect_entry.h"
#include "sim/yaml/model_reader_of.h"
#include "sim/yaml/size_limits.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {
using namespace sim::core;
using namespace sim::world;
using namespace sim::scene;
using sim::collision::overlappingPart;

namespace {

class SceneReader : public ModelReaderOf<Reader, SceneReader, SceneDef> {
 public:
  using ModelReaderOf::ModelReaderOf;

  // sceneSourceText has read `dimensions`; a 3D scene's model is sim/yaml3d's to read
  void checkDimensions(const YAML::Node& root, int dimensions) const {
    if (dimensions != 2)
      fail(root["dimensions"], "this reads 2D scenes, and this one is 3D (dimensions: 3); read it with sim::yaml3d::readModel");
  }

  void readBodies(const YAML::Node& list, SceneDef& s) {
    for (const YAML::Node& b : list) s.bodies.push_back(readBody(b));
  }

  // sim: the method, its iterations and options, the integrator and dt; an option that the chosen
  // method does not have is refused at its key
  void readSim(const YAML::Node& sim, SceneDef& s) {
    checkKeys(sim,
              {"integrator", "dt", "collisions", "iterations", "position_iterations", "substeps", "contact_hertz", "threads",
               "precision", "sleep", "recycle", "max_steps", "max_bodies", "max_vertices", "max_entries", "max_parts"},
              "sim");
    optional(sim, "max_steps", s.maxSteps, &Reader::positive);
    readSizeLimits(*this, sim, limits_);
    if (sim["collisions"]) {
      s.collisions = named(sim["collisions"], "collisions", collisionMethodFromName, kCollisionMethodNames.list());
      s.collisionsLoc = place(sim["collisions"]);
    }
    readIterations(sim, s);
    if (sim["substeps"]) s.substeps = wholeNumber(sim["substeps"], "substeps", 1, 1000);
    optional(sim, "contact_hertz", s.contactHertz, &Reader::positive);
    optional(sim, "sleep", s.sleep, &Reader::boolean);
    if (s.sleep && (s.collisions == CollisionMethod::None || s.collisions == CollisionMethod::Event ||
                    s.collisions == CollisionMethod::Isolated))
      fail(sim["sleep"], "'sleep: true' puts resting islands of the stack solvers to sleep, and 'collisions: " +
                             std::string(collisionMethodName(s.collisions)) +
                             "' has none; use 'collisions: sequential', 'soft_step' or 'auto', or drop 'sleep'");
    if (const YAML::Node recycle = sim["recycle"]) readRecycle(recycle, s);
    if (sim["threads"]) s.threads = wholeNumber(sim["threads"], "threads", 1, sim::core::settings::kMaxThreads);
    if (sim["precision"]) s.precision = named(sim["precision"], "precision", precisionFromName, kPrecisionNames.list());
    if (sim["integrator"]) {
      s.integrator = named(sim["integrator"], "integrator", integratorFromName, kIntegratorNames.list());
      s.integratorLoc = place(sim["integrator"]);
    }
    optional(sim, "dt", s.dt, &Reader::positive);
  }

  // sim: {recycle: ...}: on or off, or on with its distance: {distance: m}; soft_step's alone
  void readRecycle(const YAML::Node& recycle, SceneDef& s) {
    if (recycle.IsMap()) {
      checkKeys(recycle, {"distance"}, "recycle");
      s.recycleDistance = positive(required(recycle, "distance", "'recycle'"), "distance");
    } else {
      s.recycleDistance = boolean(recycle, "recycle") ? sim::core::settings::kRecycleDistance : 0.0;
    }
    if (s.recycleDistance > 0.0 && s.collisions != CollisionMethod::SoftStep)
      fail(recycle, "'recycle' keeps the manifolds of soft_step's resting pairs, and 'collisions: " +
                        std::string(collisionMethodName(s.collisions)) +
                        "' is not soft_step; use 'collisions: soft_step' or drop 'recycle'");
  }

  Shape readShape(const YAML::Node& n, BodyDef& body) {
    checkKeys(n, {"box", "polygon", "circle", "plane", "compound"}, "shape");
    if (n.size() != 1)
      fail(n,
           "a shape is exactly one of {box: [w, h]}, {polygon: [[x, y], ...]}, {circle: r}, {plane: {point, normal}}, "
           "{compound: [PART, ...]}");
    if (const YAML::Node parts = n["compound"]) return readCompound(parts, body);
    try {
      if (const YAML::Node plane = n["plane"]) {
        checkKeys(plane, {"point", "normal"}, "plane");
        const YAML::Node normal = required(plane, "normal", "a plane");
        try {
          return makePlane(vec2(normal, "normal"));
        } catch (const std::invalid_argument& e) {
          fail(normal, e.what());
        }
      }
      return readConvex(n);
    } catch (const std::invalid_argument& e) {
      fail(n, e.what());
    }
  }

  // the box, circle or polygon a map names (a body's shape, or a part of one)
  Shape readConvex(const YAML::Node& n) {
    if (const YAML::Node box = n["box"]) {
      const Vec2 size = vec2(box, "box");
      if (!(size.x() > 0.0) || !(size.y() > 0.0)) fail(box, "box width and height must be positive");
      return makeBox(size.x(), size.y());
    }
    if (const YAML::Node circle = n["circle"]) return makeCircle(positive(circle, "circle"));
    const YAML::Node poly = n["polygon"];
    if (!poly.IsSequence()) fail(poly, "expected a list of [x, y] vertices for 'polygon', got " + describe(poly));
    checkVertexCount(*this, poly, limits_);
    std::vector<Vec2> vertices;
    for (const YAML::Node& v : poly) vertices.push_back(vec2(v, "polygon vertex"));
    return makePolygon(std::move(vertices));
  }

  // {compound: [PART, ...]}: each part a box, polygon or circle with its position and angle in the
  // body's own frame and, optionally, its own density; parts may touch but not overlap
  Shape readCompound(const YAML::Node& list, BodyDef& body) {
    if (!list.IsSequence())
      fail(list, "expected a list of parts for 'compound', e.g. [{box: [1, 0.2]}, {circle: 0.3, position: [0.5, 0]}]");
    if (list.size() < 2)
      fail(list,
           "a body of parts needs at least two; for one shape give it as the body's 'shape' itself (and "
           "'center_of_mass' to move its center of mass)");
    checkPartCount(*this, list, limits_);
    std::vector<ShapePart> parts;
    for (const YAML::Node& p : list) {
      if (!p.IsMap())
        fail(p, "a part is a map such as {box: [w, h], position: [x, y], angle: a, density: d}, got " + describe(p));
      checkKeys(p, {"box", "polygon", "circle", "position", "angle", "density"}, "a part");
      const int shapes = (p["box"] ? 1 : 0) + (p["polygon"] ? 1 : 0) + (p["circle"] ? 1 : 0);
      if (shapes != 1) fail(p, "a part is exactly one of box, polygon or circle, with its position, angle and density");
      ShapePart part;
      try {
        part.shape = readConvex(p);
      } catch (const std::invalid_argument& e) {
        fail(p, e.what());
      }
      Vec2 position = Vec2::Zero();
      double angle = 0.0;
      optional(p, "position", position, &Reader::vec2);
      optional(p, "angle", angle, &Reader::finite);
      part.pose = {position, Rot::fromAngle(angle)};
      std::optional<double> density;
      optional(p, "density", density, &Reader::positive);
      body.partDensities.push_back(density);
      parts.push_back(std::move(part));
    }
    const Shape shape = makeCompound(std::move(parts));
    if (const std::optional<int> k = overlappingPart(shape, settings::kPartOverlapTolerance * boundingRadius(shape)))
      fail(list[*k],
           "this part overlaps an earlier part of the same body; parts may touch but not overlap: move it or "
           "make the two one polygon");
    return shape;
  }

  BodyDef readBody(const YAML::Node& n) {
    checkKeys(n,
              with({"name", "shape", "density", "mass", "inertia", "center_of_mass", "position", "angle", "velocity",
                    "angular_velocity", "static", "restitution", "friction"},
                   others_.body),
              "a body");
    BodyDef b;
    b.loc = {n.Mark().line + 1, n.Mark().column + 1};
    b.name = uniqueName(n);
    b.shape = readShape(required(n, "shape", "body '" + b.name + "'"), b);
    optional(n, "density", b.density, &Reader::positive);
    optional(n, "center_of_mass", b.centerOfMass, &Reader::vec2);
    optional(n, "mass", b.mass, &Reader::positive);
    optional(n, "inertia", b.inertia, &Reader::positive);
    optional(n, "position", b.position, &Reader::vec2);
    optional(n, "angle", b.angle, &Reader::finite);
    optional(n, "velocity", b.velocity, &Reader::vec2);
    optional(n, "angular_velocity", b.angularVelocity, &Reader::finite);
    optional(n, "static", b.isStatic, &Reader::boolean);
    if (n["restitution"]) b.restitution = restitution(n["restitution"]);
    optional(n, "friction", b.friction, &Reader::nonNegative);
    if (b.shape.kind == ShapeKind::Plane) {
      // a half-plane is an obstacle: static, placed by its point
      if (n["static"] && !b.isStatic) fail(n["static"], "a plane is always static");
      for (const char* key : {"position", "angle", "density", "mass", "inertia", "center_of_mass"})
        if (n[key]) fail(n[key], std::string("a plane has no '") + key + "'; place it with its 'point' and 'normal'");
      b.isStatic = true;
      const YAML::Node plane = n["shape"]["plane"];
      optional(plane, "point", b.position, &Reader::vec2);
    }
    if (b.isStatic && b.centerOfMass)
      fail(n["center_of_mass"], "a static body never moves, so where its mass is does not matter; drop 'center_of_mass'");
    if (b.isStatic && b.shape.kind == ShapeKind::Compound)
      fail(n["static"],
           "a static body cannot be made of parts yet; give each part as a static body of its own (static bodies "
           "never move, so nothing is lost)");
    if (b.isStatic && (b.velocity != Vec2::Zero() || b.angularVelocity != 0.0))
      fail(n, "static body '" + b.name + "' cannot move; remove its velocity or make it dynamic");
    // what the numbers make must be numbers too: a mass of 1e308 spread over a shape overflows its
    // inertia, and the energies made of it are then inf and nan
    if (!b.isStatic) {
      const auto toText = [](double x) {
        std::ostringstream m;
        m << x;
        return m.str();
      };
      const sim::scene::MassProperties mp = sim::scene::massProperties(b);
      const double reach = boundingRadius(b.shape);
      const double speed = b.velocity.norm() + std::abs(b.angularVelocity) * reach;
      if (!std::isfinite(mp.mass) || !std::isfinite(mp.inertia) || !(mp.inertia > 0.0))
        fail(n["mass"]      ? n["mass"]
             : n["density"] ? n["density"]
             : n["inertia"] ? n["inertia"]
                            : n,
             "body '" + b.name + "': its mass or moment of inertia is not a finite positive number (mass " + toText(mp.mass) +
                 ", inertia " + toText(mp.inertia) + "); choose a smaller mass or density");
      if (!std::isfinite(mp.mass * speed * speed) || !std::isfinite(mp.inertia * b.angularVelocity * b.angularVelocity))
        fail(n["angular_velocity"] ? n["angular_velocity"]
             : n["velocity"]       ? n["velocity"]
                                   : n,
             "body '" + b.name + "': its kinetic energy is not a finite number; choose a smaller speed or mass");
    }
    return b;
  }

  ExpectDef readExpect(const YAML::Node& n, const SceneDef& s) {
    checkKeys(n,
              {"time", "body", "position", "angle", "velocity", "angular_velocity", "kinetic_energy", "potential_energy",
               "total_energy", "momentum", "angular_momentum", "energy_never_rises", "tolerance", "source"},
              "an expect entry");
    ExpectDef e;
    readExpectHead(*this, n, s, {"position", "angle", "velocity", "angular_velocity"}, e);
    optional(n, "position", e.position, &Reader::vec2);
    optional(n, "angle", e.angle, &Reader::finite);
    optional(n, "velocity", e.velocity, &Reader::vec2);
    optional(n, "angular_velocity", e.angularVelocity, &Reader::finite);
    readExpectMomenta(*this, n, e, &Reader::finite);
    readExpectTolerance(*this, n, e);
    return e;
  }
};

}  // namespace

SceneDef readModel(const SceneSource& source, const OtherKeys& others) {
  return readGuarded(source.file, [&] { return SceneReader(source, others).read(source); });
}

SceneDef loadSceneText(const std::string& text, const std::string& file, const std::string& variant) {
  return readModel(sceneSourceText(text, file, variant));
}

SceneDef loadSceneFile(const std::string& path, const std::string& variant) { return readModel(readSceneSource(path, variant)); }

}  // namespace sim::yaml

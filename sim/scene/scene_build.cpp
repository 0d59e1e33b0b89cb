#include "sim/scene/scene_build.h"

#include <stdexcept>

namespace sim::scene {
using namespace sim::core;
using namespace sim::collision;
using namespace sim::world;

int SceneDef::bodyIndex(const std::string& n) const {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == n) return static_cast<int>(i);
  return -1;
}

std::unordered_map<std::string, int> SceneDef::bodyIndices() const {
  std::unordered_map<std::string, int> out;
  for (size_t i = 0; i < bodies.size(); ++i) out.emplace(bodies[i].name, static_cast<int>(i));
  return out;
}

MassProperties massProperties(const BodyDef& def) {
  if (def.shape.kind == ShapeKind::Plane) return {};
  const AreaProperties a = areaProperties(def.shape);
  const double density = def.density.value_or(settings::kDefaultDensity);
  MassProperties m;
  m.centroid = a.centroid;
  m.mass = def.mass.value_or(density * a.area);
  // a given mass spreads uniformly over the shape unless the inertia is given too
  m.inertia = def.inertia.value_or(m.mass / a.area * a.secondMoment);
  return m;
}

World buildWorld(const SceneDef& def) {
  World w;
  w.integrator = def.integrator;
  w.dt = def.dt;
  w.forces.gravity = def.gravity;
  w.collisions = def.collisions;
  w.velocityIterations = def.velocityIterations;
  w.positionIterations = def.positionIterations;
  w.substeps = def.substeps;
  w.contactHertz = def.contactHertz;
  w.sleep = def.sleep;
  w.threads = def.threads;
  w.precision = def.precision;

  // body points are written in the shape's coordinates; the body origin moves to the centroid
  std::vector<Vec2> centroid;
  for (const BodyDef& bd : def.bodies) {
    const MassProperties mp = massProperties(bd);
    centroid.push_back(mp.centroid);
    Body b;
    b.shape = shifted(bd.shape, mp.centroid);
    b.mass = mp.mass;
    b.invMass = 1.0 / mp.mass;
    b.inertia = mp.inertia;
    b.invInertia = 1.0 / mp.inertia;
    b.setState({bd.position, bd.angle, bd.velocity, bd.angularVelocity});
    b.restitution = bd.restitution.value_or(def.restitution);
    b.friction = bd.friction.value_or(def.friction.value_or(settings::kDefaultFriction));
    b.frictionNamed = bd.friction.has_value() || def.friction.has_value();
    if (bd.isStatic) b.makeStatic();
    w.bodies.push_back(std::move(b));
  }
  // the readers check every name; a definition changed after reading (a stability search) must too
  const std::unordered_map<std::string, int> indices = def.bodyIndices();
  auto index = [&](const std::string& name) {
    const auto it = indices.find(name);
    const int i = it == indices.end() ? -1 : it->second;
    if (i < 0)
      throw std::invalid_argument("a force, spring, drag or event names body '" + name + "', which the scene does not have");
    return i;
  };
  auto local = [&](const std::string& name, const Vec2& p) { return Vec2(p - centroid[index(name)]); };

  for (const PointForceDef& f : def.pointForces)
    w.forces.pointForces.push_back({index(f.body), local(f.body, f.point), f.force, f.bodyFrame, f.from, f.until});
  for (const SpringDef& s : def.springs) {
    Spring sp{index(s.body), local(s.body, s.point), kWorldAnchor, s.anchor, s.stiffness, s.restLength, s.damping};
    if (!s.body2.empty()) {
      sp.bodyB = index(s.body2);
      sp.pointB = local(s.body2, s.point2);
    }
    w.forces.springs.push_back(sp);
  }
  for (const DragDef& d : def.drags) w.forces.drags.push_back({index(d.body), d.linear, d.angular});
  for (const EventDef& e : def.events)
    w.events.push_back({e.time, index(e.body), e.pointInWorld ? e.point : local(e.body, e.point), e.pointInWorld, e.impulse});
  return w;
}

}  // namespace sim::scene

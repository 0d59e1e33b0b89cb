#include "sim/scene3d/scene_build.h"

namespace sim::scene3d {
using sim::core::DragDef;
using namespace sim::world3d;

MassProperties massProperties(const BodyDef& b) {
  // the shape at unit density: its volume and its inertia per kg/m³
  const MassProperties unit = massProperties(b.shape, 1.0);
  const double density = b.density.value_or(b.mass ? *b.mass / unit.mass : settings::kDefaultDensity);
  MassProperties out;
  out.mass = b.mass.value_or(density * unit.mass);
  // given only the mass, the mass is spread uniformly over the shape
  out.inertia = b.inertia.value_or(out.mass / unit.mass * unit.inertia);
  return out;
}

Body buildBody(const BodyDef& def) {
  const MassProperties p = massProperties(def);
  Body b = makeBody(def.shape, p.mass, p.inertia);
  b.x = def.position;
  b.q = def.orientation;
  b.v = def.velocity;
  b.omega = def.angularVelocity;
  if (def.restitution) b.restitution = *def.restitution;
  if (def.friction) b.friction = *def.friction;
  b.frictionNamed = def.friction.has_value();
  return b;
}

World buildWorld(const SceneDef& s) {
  // every name looked up in one index (the readers checked each)
  const std::unordered_map<std::string, int> indices = s.bodyIndices();
  const auto index = [&](const std::string& name) { return indices.at(name); };
  WorldDef w;
  std::vector<Body> bodies;
  // a body's or plane's own coefficients, else the world's (2D's rule for friction: contact.h)
  for (const BodyDef& def : s.bodies) {
    Body b = buildBody(def);
    b.restitution = def.restitution.value_or(s.restitution);
    b.friction = def.friction.value_or(s.friction.value_or(sim::core::settings::kDefaultFriction));
    b.frictionNamed = def.friction.has_value() || s.friction.has_value();
    bodies.push_back(b);
  }
  for (const PlaneDef& p : s.planes) {
    const bool named = p.friction.has_value() || s.friction.has_value();
    w.planes.push_back({p.point, p.normal, p.restitution.value_or(s.restitution),
                        p.friction.value_or(s.friction.value_or(sim::core::settings::kDefaultFriction)), named});
  }
  s.defineRun(w);
  w.integrator = s.integrator;
  w.normalizeQuaternions = s.normalize;
  for (const PointForceDef& f : s.pointForces)
    w.forces.pointForces.push_back({index(f.body), f.point, f.force, f.bodyFrame, f.from, f.until});
  for (const SpringDef& sp : s.springs) {
    const bool anchored = sp.body2.empty();
    w.forces.springs.push_back({index(sp.body), sp.point, anchored ? sim::core::kWorldAnchor : index(sp.body2),
                                anchored ? sp.anchor : sp.point2, sp.stiffness, sp.restLength, sp.damping});
  }
  for (const DragDef& d : s.drags) w.forces.drags.push_back({index(d.body), d.linear, d.angular});
  for (const EventDef& e : s.events) w.events.push_back({e.time, index(e.body), e.point, e.pointInWorld, e.impulse});
  return World(std::move(w), std::move(bodies));
}

}  // namespace sim::scene3d

#include "sim/scene/scene_build.h"

#include <stdexcept>

namespace sim::scene {
using namespace sim::core;
using namespace sim::collision;
using namespace sim::world;

namespace {

// a body of parts as the notes define its mass properties: M = Σ mᵢ, the center of mass
// c = Σ mᵢ cᵢ / M, and I = Σ (Iᵢ + mᵢ |cᵢ − c|²) about it (the parallel-axis theorem), each part of
// its own density or the body's
MassProperties partsMassProperties(const BodyDef& def, double density) {
  MassProperties m;
  std::vector<double> masses;
  std::vector<Vec2> centroids;
  for (size_t k = 0; k < def.shape.parts.size(); ++k) {
    const ShapePart& part = def.shape.parts[k];
    const AreaProperties a = areaProperties(part.shape);
    const double rho = k < def.partDensities.size() && def.partDensities[k] ? *def.partDensities[k] : density;
    masses.push_back(rho * a.area);
    centroids.push_back(part.pose.toWorld(a.centroid));
    m.mass += masses.back();
    m.centroid += masses.back() * centroids.back();
    m.inertia += rho * a.secondMoment;
  }
  m.centroid /= m.mass;
  for (size_t k = 0; k < masses.size(); ++k) m.inertia += masses[k] * (centroids[k] - m.centroid).squaredNorm();
  return m;
}

}  // namespace

MassProperties massProperties(const BodyDef& def) {
  if (def.shape.kind == ShapeKind::Plane) return {};
  const double density = def.density.value_or(settings::kDefaultDensity);
  MassProperties m;
  if (def.shape.kind == ShapeKind::Compound) {
    m = partsMassProperties(def, density);
  } else {
    const AreaProperties a = areaProperties(def.shape);
    m.centroid = a.centroid;
    m.mass = def.mass.value_or(density * a.area);
    // a given mass spreads uniformly over the shape unless the inertia is given too
    m.inertia = m.mass / a.area * a.secondMoment;
  }
  if (def.shape.kind == ShapeKind::Compound && def.mass) {
    // a given mass spreads as the parts' densities do: the center stays, the inertia scales with it
    m.inertia *= *def.mass / m.mass;
    m.mass = *def.mass;
  }
  if (def.centerOfMass) {
    // the center of mass where the scene puts it; without an inertia about it, the shape's about its
    // centroid moved there (parallel-axis theorem)
    m.inertia += m.mass * (*def.centerOfMass - m.centroid).squaredNorm();
    m.centroid = *def.centerOfMass;
  }
  if (def.inertia) m.inertia = *def.inertia;
  return m;
}

namespace {

// the body's shape in coordinates about its center of mass `center` (a circle off its center of
// mass becomes a part placed in the body: a compound of one)
Shape bodyShape(const BodyDef& def, const Vec2& center) {
  if (def.shape.kind == ShapeKind::Circle && center != Vec2::Zero()) return shifted(makePlaced(def.shape, Pose{}), center);
  return shifted(def.shape, center);
}

}  // namespace

World buildWorld(const SceneDef& def) {
  WorldDef w;
  def.defineRun(w);
  w.integrator = def.integrator;
  w.substeps = def.substeps;
  w.contactHertz = def.contactHertz;
  w.sleep = def.sleep;
  w.threads = def.threads;
  w.precision = def.precision;
  w.recycleDistance = def.recycleDistance;

  // body points are written in the shape's coordinates; the body origin moves to the centroid
  std::vector<Vec2> centroid;
  std::vector<Body> bodies;
  for (const BodyDef& bd : def.bodies) {
    const MassProperties mp = massProperties(bd);
    centroid.push_back(mp.centroid);
    Body b;
    b.shape = bodyShape(bd, mp.centroid);
    b.mass = mp.mass;
    b.invMass = 1.0 / mp.mass;
    b.inertia = mp.inertia;
    b.invInertia = 1.0 / mp.inertia;
    // a body of parts, or with its center of mass given, is placed by its own frame
    const bool framed = bd.shape.kind == ShapeKind::Compound || bd.centerOfMass.has_value();
    const Vec2 x = framed ? Vec2(bd.position + Rot::fromAngle(bd.angle).apply(mp.centroid)) : bd.position;
    b.setState({x, bd.angle, bd.velocity, bd.angularVelocity});
    b.restitution = bd.restitution.value_or(def.restitution);
    b.friction = bd.friction.value_or(def.friction.value_or(settings::kDefaultFriction));
    b.frictionNamed = bd.friction.has_value() || def.friction.has_value();
    if (bd.isStatic) b.makeStatic();
    bodies.push_back(std::move(b));
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
  return World(std::move(w), std::move(bodies));
}

}  // namespace sim::scene

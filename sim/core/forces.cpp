#include "sim/core/forces.h"

namespace sim::core {

namespace {

Vec2 worldPoint(const std::vector<BodyState>& states, int body, const Vec2& local) { return states[body].pose().toWorld(local); }

Vec2 pointVelocity(const BodyState& s, const Vec2& r) { return s.v + cross(s.omega, r - s.x); }

// the force f at world point r on body i: f to the center of mass, r′ × f to the torque
void applyAt(const std::vector<BodyState>& states, int i, const Vec2& r, const Vec2& f, std::vector<Vec2>& force,
             std::vector<double>& torque) {
  force[i] += f;
  torque[i] += cross(r - states[i].x, f);
}

}  // namespace

void ForceSet::accumulate(double window, const std::vector<Body>& bodies, const std::vector<BodyState>& states,
                          std::vector<Vec2>& force, std::vector<double>& torque) const {
  const size_t n = bodies.size();
  force.assign(n, Vec2::Zero());
  torque.assign(n, 0.0);

  // uniform gravity acts at the center of mass: no torque
  for (size_t i = 0; i < n; ++i)
    if (!bodies[i].isStatic) force[i] += bodies[i].mass * gravity;

  for (const PointForce& p : pointForces) {
    if (window < p.from || window >= p.until) continue;
    const BodyState& s = states[p.body];
    const Vec2 f = p.bodyFrame ? s.q().apply(p.force) : p.force;
    applyAt(states, p.body, worldPoint(states, p.body, p.point), f, force, torque);
  }

  // Hooke's law plus damping of the stretch rate, along the spring
  for (const Spring& sp : springs) {
    const Vec2 a = worldPoint(states, sp.bodyA, sp.pointA);
    const bool toWorld = sp.bodyB == kWorldAnchor;
    const Vec2 b = toWorld ? sp.pointB : worldPoint(states, sp.bodyB, sp.pointB);
    const Vec2 d = b - a;
    const double length = d.norm();
    if (length == 0.0) continue;  // no direction to pull in
    const Vec2 u = d / length;
    const Vec2 va = pointVelocity(states[sp.bodyA], a);
    const Vec2 vb = toWorld ? Vec2::Zero() : pointVelocity(states[sp.bodyB], b);
    const double stretchRate = u.dot(vb - va);
    const Vec2 f = (sp.stiffness * (length - sp.restLength) + sp.damping * stretchRate) * u;
    applyAt(states, sp.bodyA, a, f, force, torque);
    if (!toWorld) applyAt(states, sp.bodyB, b, -f, force, torque);
  }

  for (const Drag& d : drags) {
    force[d.body] -= d.linear * states[d.body].v;
    torque[d.body] -= d.angular * states[d.body].omega;
  }
}

double ForceSet::potentialEnergy(const std::vector<Body>& bodies) const {
  double e = 0.0;
  // the potential of uniform gravity: -m g·x
  for (const Body& b : bodies)
    if (!b.isStatic) e -= b.mass * gravity.dot(b.x);
  for (const Spring& sp : springs) {
    const Vec2 a = bodies[sp.bodyA].pose().toWorld(sp.pointA);
    const Vec2 b = sp.bodyB == kWorldAnchor ? sp.pointB : bodies[sp.bodyB].pose().toWorld(sp.pointB);
    const double stretch = (b - a).norm() - sp.restLength;
    e += 0.5 * sp.stiffness * stretch * stretch;
  }
  return e;
}

ForcePower ForceSet::power(double window, const std::vector<BodyState>& states) const {
  ForcePower p;
  for (const PointForce& f : pointForces) {
    if (window < f.from || window >= f.until) continue;
    const BodyState& s = states[f.body];
    const Vec2 force = f.bodyFrame ? s.q().apply(f.force) : f.force;
    p.applied += force.dot(pointVelocity(s, worldPoint(states, f.body, f.point)));
  }
  // a spring's damping force c ṡ along it, on both ends: power −c ṡ², the stretch rate ṡ squared
  for (const Spring& sp : springs) {
    if (sp.damping == 0.0) continue;
    const Vec2 a = worldPoint(states, sp.bodyA, sp.pointA);
    const bool toWorld = sp.bodyB == kWorldAnchor;
    const Vec2 b = toWorld ? sp.pointB : worldPoint(states, sp.bodyB, sp.pointB);
    const Vec2 d = b - a;
    const double length = d.norm();
    if (length == 0.0) continue;
    const Vec2 vb = toWorld ? Vec2::Zero() : pointVelocity(states[sp.bodyB], b);
    const double stretchRate = (d / length).dot(vb - pointVelocity(states[sp.bodyA], a));
    p.damping -= sp.damping * stretchRate * stretchRate;
  }
  for (const Drag& d : drags)
    p.damping -= d.linear * states[d.body].v.squaredNorm() + d.angular * states[d.body].omega * states[d.body].omega;
  return p;
}

double ForceSet::pointForceWork(double window, const std::vector<BodyState>& from, const std::vector<BodyState>& to) const {
  double work = 0.0;
  for (const PointForce& f : pointForces) {
    if (window < f.from || window >= f.until) continue;
    const Vec2 moved = worldPoint(to, f.body, f.point) - worldPoint(from, f.body, f.point);
    const Vec2 force = f.bodyFrame ? 0.5 * (from[f.body].q().apply(f.force) + to[f.body].q().apply(f.force)) : f.force;
    work += force.dot(moved);
  }
  return work;
}

bool ForceSet::hasWorkingForces() const {
  if (!pointForces.empty() || !drags.empty()) return true;
  for (const Spring& sp : springs)
    if (sp.damping != 0.0) return true;
  return false;
}

}  // namespace sim::core

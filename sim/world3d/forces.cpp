#include "sim/world3d/forces.h"

namespace sim::world3d {
using sim::core::Drag;
using sim::core::kWorldAnchor;

namespace {

// one spring's ends, in world coordinates, at the given states
struct SpringEnds {
  Vec3 a, b;
};

SpringEnds ends(const Spring& sp, const std::vector<BodyState>& at) {
  const Vec3 b = sp.bodyB == kWorldAnchor ? sp.pointB : at[sp.bodyB].toWorld(sp.pointB);
  return {at[sp.bodyA].toWorld(sp.pointA), b};
}

// the force f at world point r on body i: all of f to the center, r′ × f to the torque
void applyAt(const BodyState& s, const Vec3& r, const Vec3& f, Wrench& w) {
  w.force += f;
  w.torque += (r - s.x).cross(f);
}

}  // namespace

void ForceSet::accumulate(double window, const std::vector<Body>& bodies, const std::vector<BodyState>& at, Wrenches& out) const {
  out.assign(bodies.size(), Wrench{});

  // uniform gravity acts at the center of mass: no torque
  for (size_t i = 0; i < bodies.size(); ++i) out[i].force += bodies[i].mass * gravity;

  for (const PointForce& p : pointForces) {
    if (window < p.from || window >= p.until) continue;
    const BodyState& s = at[p.body];
    const Vec3 f = p.bodyFrame ? Vec3(s.rotation() * p.force) : p.force;
    applyAt(s, s.toWorld(p.point), f, out[p.body]);
  }

  // Hooke's law plus damping of the stretch rate, along the spring; equal and opposite on B
  for (const Spring& sp : springs) {
    const SpringEnds e = ends(sp, at);
    const Vec3 d = e.b - e.a;
    const double length = d.norm();
    if (length == 0.0) continue;  // no direction to pull in
    const Vec3 u = d / length;
    const bool toWorld = sp.bodyB == kWorldAnchor;
    const Vec3 vb = toWorld ? Vec3::Zero() : at[sp.bodyB].pointVelocity(e.b);
    const double stretchRate = u.dot(vb - at[sp.bodyA].pointVelocity(e.a));
    const Vec3 f = (sp.stiffness * (length - sp.restLength) + sp.damping * stretchRate) * u;
    applyAt(at[sp.bodyA], e.a, f, out[sp.bodyA]);
    if (!toWorld) applyAt(at[sp.bodyB], e.b, -f, out[sp.bodyB]);
  }

  for (const Drag& d : drags) {
    out[d.body].force -= d.linear * at[d.body].v;
    out[d.body].torque -= d.angular * at[d.body].omega;
  }
}

double ForceSet::potentialEnergy(const std::vector<Body>& bodies) const {
  const std::vector<BodyState> at(bodies.begin(), bodies.end());
  // uniform gravity's −m g·x, and each spring's ½ k (stretch)²
  double e = 0.0;
  for (const Body& b : bodies) e -= b.mass * gravity.dot(b.x);
  for (const Spring& sp : springs) {
    const SpringEnds s = ends(sp, at);
    const double stretch = (s.b - s.a).norm() - sp.restLength;
    e += 0.5 * sp.stiffness * stretch * stretch;
  }
  return e;
}

double ForceSet::pointForceWork(double window, const std::vector<BodyState>& from, const std::vector<BodyState>& to) const {
  double work = 0.0;
  for (const PointForce& f : pointForces) {
    if (window < f.from || window >= f.until) continue;
    const Vec3 moved = to[f.body].toWorld(f.point) - from[f.body].toWorld(f.point);
    // a force turning with its body: the mean of its two directions (second order in the step)
    const Vec3 force = f.bodyFrame ? Vec3(0.5 * (from[f.body].rotation() + to[f.body].rotation()) * f.force) : f.force;
    work += force.dot(moved);
  }
  return work;
}

sim::core::ForcePower ForceSet::power(double, const std::vector<BodyState>& at) const {
  sim::core::ForcePower p;
  // a spring's damping force c ṡ along it, on both ends: power −c ṡ²
  for (const Spring& sp : springs) {
    if (sp.damping == 0.0) continue;
    const SpringEnds e = ends(sp, at);
    const double length = (e.b - e.a).norm();
    if (length == 0.0) continue;
    const Vec3 vb = sp.bodyB == kWorldAnchor ? Vec3::Zero() : at[sp.bodyB].pointVelocity(e.b);
    const double stretchRate = ((e.b - e.a) / length).dot(vb - at[sp.bodyA].pointVelocity(e.a));
    p.damping -= sp.damping * stretchRate * stretchRate;
  }
  for (const Drag& d : drags) p.damping -= d.linear * at[d.body].v.squaredNorm() + d.angular * at[d.body].omega.squaredNorm();
  return p;
}

bool ForceSet::dependsOnVelocity() const {
  for (const Spring& sp : springs)
    if (sp.damping != 0.0) return true;
  for (const Drag& d : drags)
    if (d.linear != 0.0 || d.angular != 0.0) return true;
  return false;
}

}  // namespace sim::world3d

// The `sequential` method: an iterative solver for many simultaneous and persistent contacts,
// as in Box2D 2.4 (Catto, "Fast and Simple Physics using Sequential Impulses", GDC 2006):
// accumulated impulses clamped, warm started from the last step by feature id, restitution from
// the normal velocity before the solve, Coulomb friction, then a separate position pass
// (nonlinear Gauss–Seidel with slop, Box2D's b2ContactSolver::SolvePositionConstraints).
#include <algorithm>

#include "sim/collision/impulse.h"
#include "sim/world/methods.h"
#include "sim/world/world.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

namespace {

Vec2 tangentOf(const Vec2& n) { return {-n.y(), n.x()}; }

// the same pair and the same features as last step start from last step's impulses
void matchWarmStart(const std::vector<Contact>& contacts, std::vector<Contact>& fresh) {
  size_t old = 0;
  for (Contact& c : fresh) {
    while (old < contacts.size() && std::make_pair(contacts[old].a, contacts[old].b) < std::make_pair(c.a, c.b)) ++old;
    if (old == contacts.size() || contacts[old].a != c.a || contacts[old].b != c.b) continue;
    const Contact& prev = contacts[old];
    for (int k = 0; k < c.manifold.count; ++k)
      for (int m = 0; m < prev.manifold.count; ++m)
        if (prev.manifold.points[m].id == c.manifold.points[k].id) {
          c.state[k].normalImpulse = prev.state[m].normalImpulse;
          c.state[k].tangentImpulse = prev.state[m].tangentImpulse;
        }
  }
}

// effective masses, anchors and the velocity each contact must reach
void prepareContacts(World& world, double h) {
  const std::vector<Body>& bodies = world.bodies;
  for (Contact& c : world.contacts) {
    const Body &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.manifold.normal, t = tangentOf(n);
    for (int k = 0; k < c.manifold.count; ++k) {
      ContactPointState& s = c.state[k];
      const ManifoldPoint& p = c.manifold.points[k];
      s.normalMass = 1.0 / inverseEffectiveMass(a, b, p.point, n);
      s.tangentMass = 1.0 / inverseEffectiveMass(a, b, p.point, t);
      s.anchorA = a.pose().toBody(p.point);
      s.anchorB = b.pose().toBody(p.point);
      const double vn = s.vnBefore = n.dot(relativeVelocity(a, b, p.point));
      // restitution from the velocity before the solve, for contacts that close within the step
      // and arrive fast enough; slower ones settle; a gap may close but not be overrun
      if (vn < -settings::kRestitutionThreshold && p.separation + h * vn < 0.0)
        s.bias = -c.restitution * vn;
      else if (p.separation > 0.0)
        s.bias = -p.separation / h;
      else
        s.bias = 0.0;
    }
  }
}

void warmStart(World& world) {
  std::vector<Body>& bodies = world.bodies;
  for (const Contact& c : world.contacts) {
    const Vec2 n = c.manifold.normal, t = tangentOf(n);
    for (int k = 0; k < c.manifold.count; ++k)
      applyImpulsePair(bodies[c.a], bodies[c.b], c.manifold.points[k].point,
                       c.state[k].normalImpulse * n + c.state[k].tangentImpulse * t);
  }
}

// both points of a two-point manifold at once: point by point, the first impulse would tip the
// body and the second undo it, so a resting box rocks (Box2D's block solver: the 2×2 linear
// complementarity problem solved by trying its four cases)
bool solveNormalBlock(std::vector<Body>& bodies, Contact& c) {
  Body &a = bodies[c.a], &b = bodies[c.b];
  const Vec2 n = c.manifold.normal;
  const Vec2 r1 = c.manifold.points[0].point, r2 = c.manifold.points[1].point;
  ContactPointState &s1 = c.state[0], &s2 = c.state[1];
  const NormalBlock K = normalBlock(a, b, r1, r2, n, 1.0 / s1.normalMass, 1.0 / s2.normalMass);
  const double k11 = K.k11, k12 = K.k12, k22 = K.k22;
  // an ill-conditioned pair (the two points nearly one) is left to the point-by-point sweep
  if (!(k11 * k11 < settings::kMaxConditionNumber * K.det)) return false;

  // with x the new accumulated impulses: v_n = K x + b' must be ≥ 0 where x > 0, x ≥ 0
  const double x1Old = s1.normalImpulse, x2Old = s2.normalImpulse;
  const double b1 = n.dot(relativeVelocity(a, b, r1)) - s1.bias - (k11 * x1Old + k12 * x2Old);
  const double b2 = n.dot(relativeVelocity(a, b, r2)) - s2.bias - (k12 * x1Old + k22 * x2Old);
  double x1 = 0.0, x2 = 0.0;
  if (const Vec2 both = K.solve(-b1, -b2); both.x() >= 0.0 && both.y() >= 0.0) {
    x1 = both.x(), x2 = both.y();  // both points push
  } else if (const double z1 = -b1 / k11; z1 >= 0.0 && k12 * z1 + b2 >= 0.0) {
    x1 = z1;  // only the first
  } else if (const double z2 = -b2 / k22; z2 >= 0.0 && k12 * z2 + b1 >= 0.0) {
    x2 = z2;  // only the second
  } else if (!(b1 >= 0.0 && b2 >= 0.0)) {
    return false;  // no case fits (round-off): fall back to the sweep
  }
  applyImpulsePair(a, b, r1, (x1 - x1Old) * n);
  applyImpulsePair(a, b, r2, (x2 - x2Old) * n);
  s1.normalImpulse = x1;
  s2.normalImpulse = x2;
  return true;
}

// one Gauss–Seidel sweep over the contacts: friction, then the normal impulses
void solveVelocities(World& world) {
  std::vector<Body>& bodies = world.bodies;
  for (Contact& c : world.contacts) {
    Body &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.manifold.normal, t = tangentOf(n);
    // Coulomb friction: the accumulated tangent impulse stays within ±μ times the normal one
    if (c.friction > 0.0)
      for (int k = 0; k < c.manifold.count; ++k) {
        ContactPointState& s = c.state[k];
        const Vec2 r = c.manifold.points[k].point;
        const double lambda = -s.tangentMass * t.dot(relativeVelocity(a, b, r));
        const double limit = c.friction * s.normalImpulse;
        const double total = std::clamp(s.tangentImpulse + lambda, -limit, limit);
        applyImpulsePair(a, b, r, (total - s.tangentImpulse) * t);
        s.tangentImpulse = total;
      }
    if (c.manifold.count == 2 && solveNormalBlock(bodies, c)) continue;
    // the normal impulse pushes, never pulls: clamp the accumulated impulse at zero
    for (int k = 0; k < c.manifold.count; ++k) {
      ContactPointState& s = c.state[k];
      const Vec2 r = c.manifold.points[k].point;
      const double lambda = -s.normalMass * (n.dot(relativeVelocity(a, b, r)) - s.bias);
      const double total = std::max(s.normalImpulse + lambda, 0.0);
      applyImpulsePair(a, b, r, (total - s.normalImpulse) * n);
      s.normalImpulse = total;
    }
  }
}

// one pass of position correction; true when every contact is within the slop
bool solvePositions(World& world) {
  std::vector<Body>& bodies = world.bodies;
  double deepest = 0.0;
  for (const Contact& c : world.contacts) {
    Body &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.manifold.normal;
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPointState& s = c.state[k];
      const ManifoldPoint& p = c.manifold.points[k];
      // the separation now: the contact's material points have moved apart along n̂ by this much
      const Vec2 pa = a.pose().toWorld(s.anchorA), pb = b.pose().toWorld(s.anchorB);
      const double separation = p.separation + n.dot(pa - pb);
      deepest = std::min(deepest, separation);
      const double correction = std::clamp(settings::kPositionCorrection * (separation + settings::kLinearSlop),
                                           -settings::kMaxLinearCorrection, 0.0);
      if (correction == 0.0) continue;
      const Vec2 r = 0.5 * (pa + pb);
      const double kInv = inverseEffectiveMass(a, b, r, n);
      if (kInv == 0.0) continue;
      const Vec2 push = (-correction / kInv) * n;
      const Vec2 ra = r - a.x, rb = r - b.x;
      a.x += a.invMass * push;
      a.angle += a.invInertia * cross(ra, push);
      b.x -= b.invMass * push;
      b.angle -= b.invInertia * cross(rb, push);
    }
  }
  // Box2D stops when the deepest point is within three times the slop
  return deepest >= -settings::kPositionSolvedDepth;
}

// the impacts of the step: contacts that arrived faster than the restitution threshold
void recordImpacts(World& world, double t) {
  for (const Contact& c : world.contacts)
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPointState& s = c.state[k];
      if (s.vnBefore >= -settings::kRestitutionThreshold || s.normalImpulse <= 0.0) continue;
      const Vec2 r = c.manifold.points[k].point, n = c.manifold.normal;
      ImpactRecord rec{t, c.a, c.b, r, n, s.normalImpulse, s.tangentImpulse};
      rec.vnBefore = s.vnBefore;
      rec.vnAfter = n.dot(relativeVelocity(world.bodies[c.a], world.bodies[c.b], r));
      world.impacts.push_back(rec);
    }
}

class SequentialSolver final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<SequentialSolver>(*this); }

  // the contacts where the bodies are now, carrying over last step's impulses (warm starting)
  void beginStep(World& world, const TimeStep& step) override {
    std::vector<Contact> fresh = world.findContacts(settings::kContactMargin);
    matchWarmStart(world.contacts, fresh);
    world.contacts = std::move(fresh);
    prepareContacts(world, step.h);
  }

  // move freely, remembering where the step began and where the free motion ends
  bool move(World& world, const TimeStep& step) override {
    before_ = world.states();
    moveFreely(world, step);
    free_ = world.states();
    return false;
  }

  // the contacts solved on the free velocities from where the step began, then the positions
  void resolveCollisions(World& world, const TimeStep& step) override {
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      world.bodies[i].x = before_[i].x;
      world.bodies[i].angle = before_[i].angle;
    }
    warmStart(world);
    for (int k = 0; k < world.velocityIterations; ++k) solveVelocities(world);
    integratePositions(world, step.h);
    for (int k = 0; k < world.positionIterations; ++k)
      if (solvePositions(world)) break;
    recordImpacts(world, step.end());
  }

 private:
  // the free motion plus the contact velocity change over the step (for symplectic Euler this is
  // exactly x + h v⁺, Box2D's integration of positions)
  void integratePositions(World& world, double h) const {
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      Body& b = world.bodies[i];
      if (b.isStatic) continue;
      b.x = free_[i].x + h * (b.v - free_[i].v);
      b.angle = free_[i].angle + h * (b.omega - free_[i].omega);
    }
  }

  States before_, free_;  // the states where the step began and where the free motion ended
};

}  // namespace

std::unique_ptr<Method> makeSequentialSolver() { return std::make_unique<SequentialSolver>(); }

}  // namespace sim::world

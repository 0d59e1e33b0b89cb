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

// A gap may close within the step (a speculative contact) where the point arrives: it carried no
// load last step, or the gap is wider than the slop. A loaded point within the slop counts as
// touching (Box2D 2.4's points only exist touching): in a tall pile the position pass opens such
// gaps every step, and letting them close at s/h turned its pushes into approach speed, so the
// pile breathed (base-100 pyramid's fastest body 1.68 → 1.39 m/s, Box2D 1.40)
bool gapMayClose(double warmNormalImpulse, double separation) {
  return warmNormalImpulse == 0.0 || separation > settings::kLinearSlop;
}

// The inner loops run on flat arrays built once per step (Box2D v3's contact constraints): the
// bodies' velocities and mass in one contiguous array, each contact's points with their lever arms
// and, for two points, the block solver's matrix, so that the loops touch no Body, compute no
// rotation and allocate nothing. Every quantity is the one the loops computed from the bodies
// before, by the same operations, so the results are the same to the bit.

// what the velocity loops read and change of a body
struct VelocityBody {
  Vec2 v = Vec2::Zero();
  double omega = 0.0;
  double invMass = 0.0, invInertia = 0.0;
};

// what the position loop reads and changes of a body; the rotation follows the angle on demand
struct PositionBody {
  Vec2 x = Vec2::Zero();
  double angle = 0.0;
  double invMass = 0.0, invInertia = 0.0;
  Rot q;
  bool rotationStale = true;
  const Rot& rotation() {
    if (rotationStale) q = Rot::fromAngle(angle), rotationStale = false;
    return q;
  }
};

// one manifold point, prepared once per step
struct SolverPoint {
  Vec2 rA = Vec2::Zero(), rB = Vec2::Zero();         // from each center of mass to the point, at the step's start
  double normalMass = 0.0, tangentMass = 0.0;        // effective masses along n̂ and the tangent
  double bias = 0.0;                                 // lowest normal velocity allowed: restitution or a closing gap
  double normalImpulse = 0.0, tangentImpulse = 0.0;  // accumulated; warm started from the contact
};

// what the velocity loops read of a contact (kept small: the loops stream through all of them)
struct SolverContact {
  int a = 0, b = 0, count = 0;
  bool block = false;  // two points, well conditioned: solved together
  Vec2 n = Vec2::UnitY();
  double friction = 0.0;
  NormalBlock K;
  double inverse11 = 0.0, inverse12 = 0.0, inverse22 = 0.0;  // K⁻¹, for the block solver
  SolverPoint p[2];
};

// what the position pass reads of a contact's point, beside its SolverContact
struct PositionPoint {
  Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();  // body coordinates
  double separation = 0.0;                              // at the step's start
};

// a contact's flat constraint: effective masses, lever arms, anchors, the velocity each point must
// reach (and the normal velocity before the solve, for the impacts), its warm-start impulses
void buildConstraint(const Contact& c, const Body& a, const Body& b, const Pose& poseA, const Pose& poseB, double h,
                     SolverContact& s, PositionPoint anchors[2], double vnBefore[2]) {
  s.a = c.a, s.b = c.b, s.count = c.manifold.count;
  s.n = c.manifold.normal;
  s.friction = c.friction;
  const Vec2 n = s.n, t = tangentOf(n);
  for (int k = 0; k < s.count; ++k) {
    const ManifoldPoint& mp = c.manifold.points[k];
    SolverPoint& p = s.p[k];
    p.normalMass = 1.0 / inverseEffectiveMass(a, b, mp.point, n);
    p.tangentMass = 1.0 / inverseEffectiveMass(a, b, mp.point, t);
    anchors[k] = {poseA.toBody(mp.point), poseB.toBody(mp.point), mp.separation};
    const double vn = vnBefore[k] = n.dot(relativeVelocity(a, b, mp.point));
    p.normalImpulse = c.state[k].normalImpulse, p.tangentImpulse = c.state[k].tangentImpulse;
    // restitution from the velocity before the solve, for contacts that close within the step
    // and arrive fast enough; slower ones settle; a gap may close but not be overrun
    if (vn < -settings::kRestitutionThreshold && mp.separation + h * vn < 0.0) p.bias = -c.restitution * vn;
    else if (mp.separation > 0.0 && gapMayClose(p.normalImpulse, mp.separation)) p.bias = -mp.separation / h;
    else p.bias = 0.0;
    p.rA = mp.point - a.x, p.rB = mp.point - b.x;
  }
  s.block = false;
  if (s.count == 2) {
    s.K = normalBlock(a, b, c.manifold.points[0].point, c.manifold.points[1].point, s.n, 1.0 / s.p[0].normalMass,
                      1.0 / s.p[1].normalMass);
    // an ill-conditioned pair (the two points nearly one) is left to the point-by-point sweep
    s.block = s.K.k11 * s.K.k11 < settings::kMaxConditionNumber * s.K.det;
    // K⁻¹ once per step, so that the loops multiply where they divided (Box2D 2.4's
    // normalMass = K.GetInverse(); results change at round-off)
    const double inverseDet = 1.0 / s.K.det;
    s.inverse11 = inverseDet * s.K.k22, s.inverse12 = -inverseDet * s.K.k12, s.inverse22 = inverseDet * s.K.k11;
  }
}

// every contact's flat constraint, in one pass (each contact is read once); at the step's start,
// where the constraints' positions and impulses are those the loops begin from
void prepareContacts(const World& world, double h, std::vector<Pose>& poses, std::vector<SolverContact>& out,
                     std::vector<PositionPoint>& anchors, std::vector<double>& vnBefore) {
  const std::vector<Body>& bodies = world.bodies;
  // each body's pose once (one sine and cosine), for every contact it is in
  poses.resize(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) poses[i] = bodies[i].pose();
  out.resize(world.contacts.size());
  anchors.resize(2 * world.contacts.size());
  vnBefore.resize(2 * world.contacts.size());
  for (size_t i = 0; i < world.contacts.size(); ++i) {
    const Contact& c = world.contacts[i];
    buildConstraint(c, bodies[c.a], bodies[c.b], poses[c.a], poses[c.b], h, out[i], &anchors[2 * i], &vnBefore[2 * i]);
  }
}

void warmStart(std::vector<VelocityBody>& bodies, const std::vector<SolverContact>& contacts) {
  for (const SolverContact& c : contacts)
    for (int k = 0; k < c.count; ++k)
      applyAt(bodies[c.a], bodies[c.b], c.p[k], c.p[k].normalImpulse * c.n + c.p[k].tangentImpulse * tangentOf(c.n));
}

// both points of a two-point manifold at once: point by point, the first impulse would tip the
// body and the second undo it, so a resting box rocks (Box2D's block solver: the 2×2 linear
// complementarity problem solved by trying its four cases)
bool solveNormalBlock(std::vector<VelocityBody>& bodies, SolverContact& c) {
  VelocityBody &a = bodies[c.a], &b = bodies[c.b];
  const Vec2 n = c.n;
  SolverPoint &s1 = c.p[0], &s2 = c.p[1];
  const double k11 = c.K.k11, k12 = c.K.k12, k22 = c.K.k22;

  // with x the new accumulated impulses: v_n = K x + b' must be ≥ 0 where x > 0, x ≥ 0
  const double x1Old = s1.normalImpulse, x2Old = s2.normalImpulse;
  const double b1 = n.dot(relativeVelocityAt(a, b, s1)) - s1.bias - (k11 * x1Old + k12 * x2Old);
  const double b2 = n.dot(relativeVelocityAt(a, b, s2)) - s2.bias - (k12 * x1Old + k22 * x2Old);
  double x1 = 0.0, x2 = 0.0;
  // x = −K⁻¹ b', and for one point alone x_i = −b'_i / K_ii, with the inverses prepared (Box2D 2.4)
  const double y1 = -(c.inverse11 * b1 + c.inverse12 * b2), y2 = -(c.inverse12 * b1 + c.inverse22 * b2);
  if (y1 >= 0.0 && y2 >= 0.0) {
    x1 = y1, x2 = y2;  // both points push
  } else if (const double z1 = -s1.normalMass * b1; z1 >= 0.0 && k12 * z1 + b2 >= 0.0) {
    x1 = z1;  // only the first
  } else if (const double z2 = -s2.normalMass * b2; z2 >= 0.0 && k12 * z2 + b1 >= 0.0) {
    x2 = z2;  // only the second
  } else if (!(b1 >= 0.0 && b2 >= 0.0)) {
    return false;  // no case fits (round-off): fall back to the sweep
  }
  applyAt(a, b, s1, (x1 - x1Old) * n);
  applyAt(a, b, s2, (x2 - x2Old) * n);
  s1.normalImpulse = x1;
  s2.normalImpulse = x2;
  return true;
}

// one Gauss–Seidel sweep over the contacts: friction, then the normal impulses
void solveVelocities(std::vector<VelocityBody>& bodies, std::vector<SolverContact>& contacts) {
  for (SolverContact& c : contacts) {
    VelocityBody &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.n, t = tangentOf(n);
    // Coulomb friction: the accumulated tangent impulse stays within ±μ times the normal one
    if (c.friction > 0.0)
      for (int k = 0; k < c.count; ++k) solveFrictionAt(a, b, c.p[k], t, c.friction);
    if (c.block && solveNormalBlock(bodies, c)) continue;
    // the normal impulse pushes, never pulls: clamp the accumulated impulse at zero
    for (int k = 0; k < c.count; ++k) {
      SolverPoint& s = c.p[k];
      const double lambda = -s.normalMass * (n.dot(relativeVelocityAt(a, b, s)) - s.bias);
      const double total = std::max(s.normalImpulse + lambda, 0.0);
      applyAt(a, b, s, (total - s.normalImpulse) * n);
      s.normalImpulse = total;
    }
  }
}

// one pass of position correction; true when every contact is within the slop
bool solvePositions(std::vector<PositionBody>& bodies, const std::vector<SolverContact>& contacts,
                    const std::vector<PositionPoint>& anchors) {
  double deepest = 0.0;
  for (size_t i = 0; i < contacts.size(); ++i) {
    const SolverContact& c = contacts[i];
    PositionBody &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.n;
    for (int k = 0; k < c.count; ++k) {
      const PositionPoint& s = anchors[2 * i + k];
      // the separation now: the contact's material points have moved apart along n̂ by this much
      const Vec2 pa = a.x + a.rotation().apply(s.anchorA), pb = b.x + b.rotation().apply(s.anchorB);
      const double separation = s.separation + n.dot(pa - pb);
      deepest = std::min(deepest, separation);
      const double correction =
          std::clamp(settings::kPositionCorrection * (separation + settings::kLinearSlop), -settings::kMaxLinearCorrection, 0.0);
      if (correction == 0.0) continue;
      const Vec2 r = 0.5 * (pa + pb);
      const Vec2 ra = r - a.x, rb = r - b.x;
      const double kInv = inverseEffectiveMassAt(a, b, ra, rb, n);
      if (kInv == 0.0) continue;
      const Vec2 push = (-correction / kInv) * n;
      a.x += a.invMass * push;
      a.angle += a.invInertia * cross(ra, push);
      a.rotationStale = true;
      b.x -= b.invMass * push;
      b.angle -= b.invInertia * cross(rb, push);
      b.rotationStale = true;
    }
  }
  // Box2D stops when the deepest point is within three times the slop
  return deepest >= -settings::kPositionSolvedDepth;
}

// the impacts of the step: contacts that arrived faster than the restitution threshold
void recordImpacts(World& world, const std::vector<double>& vnBefore, double t) {
  for (size_t i = 0; i < world.contacts.size(); ++i) {
    const Contact& c = world.contacts[i];
    for (int k = 0; k < c.manifold.count; ++k) {
      const ContactPointState& s = c.state[k];
      if (vnBefore[2 * i + k] >= -settings::kRestitutionThreshold || s.normalImpulse <= 0.0) continue;
      const Vec2 r = c.manifold.points[k].point, n = c.manifold.normal;
      ImpactRecord rec{t, c.a, c.b, r, n, s.normalImpulse, s.tangentImpulse};
      rec.vnBefore = vnBefore[2 * i + k];
      rec.vnAfter = n.dot(relativeVelocity(world.bodies[c.a], world.bodies[c.b], r));
      world.impacts.push_back(rec);
    }
  }
}

class SequentialSolver final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<SequentialSolver>(*this); }

  // Box2D 2.4's b2World::Step as Box2D-Lite's World::Step reads: contacts, free motion, velocity
  // iterations, positions, position iterations
  void step(World& world, const TimeStep& step) override {
    // the contacts where the bodies are now, carrying over last step's impulses (warm starting),
    // prepared for the loops; polygon pairs clipped with Box2D 2.4's side slack, so that a point
    // keeps its features (and its warm start) when a box turns by a hair on one as wide
    world.findContacts(settings::kContactMargin, fresh_, nullptr, settings::kClipSideSlack);
    std::swap(world.contacts, fresh_);
    prepareContacts(world, step.h, poses_, constraints_, anchors_, vnBefore_);
    // move freely, remembering where the free motion ends
    moveFreely(world, step);
    free_ = world.states();
    // the contacts, prepared where the step began, solved on the free velocities
    std::vector<Body>& bodies = world.bodies;
    velocities_.resize(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i)
      velocities_[i] = {bodies[i].v, bodies[i].omega, bodies[i].invMass, bodies[i].invInertia};
    warmStart(velocities_, constraints_);
    for (int k = 0; k < world.def().velocityIterations; ++k) solveVelocities(velocities_, constraints_);
    for (size_t i = 0; i < bodies.size(); ++i) bodies[i].v = velocities_[i].v, bodies[i].omega = velocities_[i].omega;
    storeImpulses(world);
    // the positions from the free motion's, with the velocities the contacts changed
    integratePositions(world, step.h);
    // the position pass: nonlinear Gauss–Seidel until every contact is within the slop
    positions_.resize(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i)
      positions_[i] = {bodies[i].x, bodies[i].angle, bodies[i].invMass, bodies[i].invInertia, Rot{}, true};
    for (int k = 0; k < world.def().positionIterations; ++k)
      if (solvePositions(positions_, constraints_, anchors_)) break;
    for (size_t i = 0; i < bodies.size(); ++i) bodies[i].x = positions_[i].x, bodies[i].angle = positions_[i].angle;
    recordImpacts(world, vnBefore_, step.end());
  }

 private:
  // the free motion plus what the contacts' velocity change Δv moves the body: their impulse over
  // the step is a force P/h held for the step, moved as the integrator moves a constant force
  // (a split of smooth and contact forces, as the velocity-level time stepping of Stewart and
  // Trinkle 1996 takes the impulse over the step). Symplectic Euler: x + h v⁺, Box2D's integration
  // of positions; the midpoint rule and RK4: x + h (v + v⁺)/2 at rest, so a resting body stays,
  // where h Δv would lift it by ½ h² g every step; explicit Euler: x + h v
  void integratePositions(World& world, double h) const {
    const double reach = constantAccelerationWeight(world.def().integrator) * h;
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      Body& b = world.bodies[i];
      if (b.isStatic) continue;
      b.x = free_[i].x + reach * (b.v - free_[i].v);
      b.angle = free_[i].angle + reach * (b.omega - free_[i].omega);
    }
  }

  // the accumulated impulses back into the contacts, for the next step's warm start and the impacts
  void storeImpulses(World& world) const {
    for (size_t i = 0; i < constraints_.size(); ++i)
      for (int k = 0; k < constraints_[i].count; ++k) {
        world.contacts[i].state[k].normalImpulse = constraints_[i].p[k].normalImpulse;
        world.contacts[i].state[k].tangentImpulse = constraints_[i].p[k].tangentImpulse;
      }
  }

  States free_;  // the states where the free motion ended
  // scratch of the solver loops, kept from step to step so that a step allocates nothing
  std::vector<SolverContact> constraints_;
  std::vector<PositionPoint> anchors_;  // two per contact
  std::vector<double> vnBefore_;        // two per contact: each point's normal velocity before the solve
  std::vector<VelocityBody> velocities_;
  std::vector<PositionBody> positions_;
  std::vector<Pose> poses_;
  std::vector<Contact> fresh_;  // the contacts found, then last step's (their storage reused)
};

}  // namespace

std::unique_ptr<Method> makeSequentialSolver() { return std::make_unique<SequentialSolver>(); }

}  // namespace sim::world

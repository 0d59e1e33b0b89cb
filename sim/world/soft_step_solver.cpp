// The `soft_step` method: Box2D v3's solver as Erin Catto describes it ("Solver2D", 2024; Solver2D's
// solve_soft_step.c, Box2D v3's contact_solver.c and solver.c; written anew here). The step is cut
// into `substeps`; each integrates the velocities, solves every contact once as a soft constraint
// (a spring of the scene's contact_hertz, by default kContactHertz, with damping ratio kContactDampingRatio, relative to the substep, whose
// push-out speed is bounded), integrates the positions, and solves the contacts once more without
// the push (relax), so that the push does not stay in the bodies as energy. Restitution is applied
// once after the substeps, from the normal velocity before them. Contacts are found once per step,
// warm started by feature id, with Coulomb friction; a point with a gap is a speculative contact
// that may close it but not overrun it. There is no position pass: the soft push is the correction.
// Forces act per substep by symplectic Euler, whatever the scene's integrator.
#include <algorithm>
#include <cmath>

#include "sim/collision/impulse.h"
#include "sim/world/methods.h"
#include "sim/world/world.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

namespace {

constexpr double kPi = 3.14159265358979323846;

// a soft constraint's coefficients for a spring of `hertz` and damping ratio `zeta` over a substep
// h (Box2D v3's b2MakeSoft; Catto, "Solver2D": soft step)
struct Softness {
  double biasRate = 0.0, massScale = 1.0, impulseScale = 0.0;
};

Softness makeSoft(double hertz, double zeta, double h) {
  const double omega = 2.0 * kPi * hertz;
  const double a1 = 2.0 * zeta + h * omega, a2 = h * omega * a1, a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

// one manifold point, prepared once per step: lever arms fixed for the step (Box2D v3)
struct SoftPoint {
  Vec2 rA = Vec2::Zero(), rB = Vec2::Zero();  // from each center of mass to the point, at the step's start
  Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();  // the point in each body's coordinates
  double separation = 0.0;                    // at the step's start
  double normalMass = 0.0, tangentMass = 0.0;
  double normalImpulse = 0.0, tangentImpulse = 0.0;  // accumulated within a substep, warm started
  double totalNormalImpulse = 0.0;            // over the step's substeps: the impulse delivered
  double vnBefore = 0.0;                      // normal velocity before the step (restitution)
};

// one contact's constraint, in a flat array built once per step
struct SoftContact {
  int a = 0, b = 0;
  int count = 0;
  Vec2 n = Vec2::UnitY();  // from B to A
  double friction = 0.0, restitution = 0.0;
  Softness soft;
  SoftPoint p[2];
};

// what the substeps read and change of a body, in one contiguous array: during the substeps these
// are the bodies' state (World::bodies is written back once, after them), so the loops stream
// through small records instead of whole bodies; the same operations on the same numbers as on
// the bodies themselves, so the results are the same to the bit
struct SoftBody {
  Vec2 v = Vec2::Zero();
  double omega = 0.0;
  double invMass = 0.0, invInertia = 0.0;
  Vec2 x = Vec2::Zero();
  double angle = 0.0;
  bool isStatic = false;
};

Vec2 tangentOf(const Vec2& n) { return {-n.y(), n.x()}; }

// 1 / m_eff⁻¹ along d, or 0 where nothing can move (two static bodies)
double effectiveMass(const Body& a, const Body& b, const Vec2& rA, const Vec2& rB, const Vec2& d) {
  const double k = inverseEffectiveMassAt(a, b, rA, rB, d);
  return k > 0.0 ? 1.0 / k : 0.0;
}

// Contacts are found once per step, so a point the step will close must be found at its start: the
// margin reaches as far as the fastest body travels in the step (a speculative contact closes its
// gap and no more). With the fixed 1 cm margin, rows of Box2D's dropped pyramid landing at 2.2 m/s
// sank 2.7 cm before they were seen and the pile bulged 0.28 m; with this margin 0.041 m (issue 14,
// rigidreel_stack_bench --method soft_step --layout pyramid:20:dropped).
double speculativeMargin(const World& world, double h) {
  double fastest = 0.0;
  for (const Body& b : world.bodies)
    if (!b.isStatic) fastest = std::max(fastest, b.v.norm());
  return settings::kContactMargin + h * fastest;
}

class SoftStepSolver final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<SoftStepSolver>(*this); }

  // the contacts where the bodies are now, carrying over last step's impulses, prepared once
  void beginStep(World& world, const TimeStep& step) override {
    world.findContacts(speculativeMargin(world, step.h), fresh_);
    matchWarmStart(world.contacts, fresh_);
    std::swap(world.contacts, fresh_);
    prepare(world, step.h / world.substeps);
  }

  // the substeps: velocities, soft contacts, positions, relax
  bool move(World& world, const TimeStep& step) override {
    const int n = world.substeps;
    const double h = step.h / n;
    std::vector<Body>& bodies = world.bodies;
    bodies_.resize(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i) {
      const Body& b = bodies[i];
      bodies_[i] = {b.v, b.omega, b.invMass, b.invInertia, b.x, b.angle, b.isStatic};
    }
    for (int k = 0; k < n; ++k) {
      integrateVelocities(world, step, h);
      warmStart();
      solve(h, true);
      integratePositions(h);
      for (int r = 0; r < settings::kRelaxIterations; ++r) solve(h, false);
      for (SoftContact& c : constraints_)
        for (int i = 0; i < c.count; ++i) c.p[i].totalNormalImpulse += c.p[i].normalImpulse;
    }
    for (size_t i = 0; i < bodies.size(); ++i) {
      Body& b = bodies[i];
      b.v = bodies_[i].v, b.omega = bodies_[i].omega, b.x = bodies_[i].x, b.angle = bodies_[i].angle;
    }
    return false;
  }

  // restitution once, from the velocity before the substeps; the impulses kept for next step
  void resolveCollisions(World& world, const TimeStep& step) override {
    applyRestitution(world);
    store(world, step.end());
  }

 private:
  void prepare(World& world, double h) {
    const std::vector<Body>& bodies = world.bodies;
    // Box2D v3: contactHertz = min(contactHertz, 0.25 × substep rate); static contacts twice as stiff
    const double hertz = std::min(world.contactHertz, settings::kContactHertzPerSubstepRate / h);
    const Softness soft = makeSoft(hertz, settings::kContactDampingRatio, h);
    const Softness staticSoft = makeSoft(2.0 * hertz, settings::kContactDampingRatio, h);
    constraints_.clear();
    rotations_.resize(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i) rotations_[i] = bodies[i].q();
    for (const Contact& c : world.contacts) {
      const Body &a = bodies[c.a], &b = bodies[c.b];
      SoftContact s;
      s.a = c.a, s.b = c.b, s.count = c.manifold.count, s.n = c.manifold.normal;
      s.friction = c.friction, s.restitution = c.restitution;
      s.soft = a.isStatic || b.isStatic ? staticSoft : soft;
      const Vec2 t = tangentOf(s.n);
      for (int k = 0; k < s.count; ++k) {
        SoftPoint& p = s.p[k];
        const ManifoldPoint& m = c.manifold.points[k];
        p.rA = m.point - a.x, p.rB = m.point - b.x;
        p.localA = Pose{a.x, rotations_[c.a]}.toBody(m.point), p.localB = Pose{b.x, rotations_[c.b]}.toBody(m.point);
        p.separation = m.separation;
        p.normalMass = effectiveMass(a, b, p.rA, p.rB, s.n);
        p.tangentMass = effectiveMass(a, b, p.rA, p.rB, t);
        p.normalImpulse = c.state[k].normalImpulse;
        p.tangentImpulse = c.state[k].tangentImpulse;
        p.vnBefore = s.n.dot(relativeVelocityAt(a, b, p));
      }
      constraints_.push_back(s);
    }
  }

  // v += h (f/m), ω += h τ/I with the forces at the substep's start (symplectic Euler)
  void integrateVelocities(const World& world, const TimeStep& step, double h) {
    states_.resize(bodies_.size());
    for (size_t i = 0; i < bodies_.size(); ++i) states_[i] = {bodies_[i].x, bodies_[i].angle, bodies_[i].v, bodies_[i].omega};
    world.rates(step.midpoint(), states_, rates_);
    for (size_t i = 0; i < bodies_.size(); ++i) {
      SoftBody& b = bodies_[i];
      if (b.isStatic) continue;
      b.v += h * rates_[i].vDot;
      b.omega += h * rates_[i].omegaDot;
    }
  }

  void integratePositions(double h) {
    for (SoftBody& b : bodies_) {
      if (b.isStatic) continue;
      b.x += h * b.v;
      b.angle += h * b.omega;
    }
    for (size_t i = 0; i < bodies_.size(); ++i) rotations_[i] = Rot::fromAngle(bodies_[i].angle);
  }

  void warmStart() {
    std::vector<SoftBody>& bodies = bodies_;
    for (const SoftContact& c : constraints_) {
      const Vec2 t = tangentOf(c.n);
      for (int k = 0; k < c.count; ++k)
        applyAt(bodies[c.a], bodies[c.b], c.p[k], c.p[k].normalImpulse * c.n + c.p[k].tangentImpulse * t);
    }
  }

  // one pass over the contacts: the normal impulses (soft with the push when useBias, rigid when
  // relaxing; a gap is a speculative contact either way), then Coulomb friction
  void solve(double h, bool useBias) {
    std::vector<SoftBody>& bodies = bodies_;
    for (SoftContact& c : constraints_) {
      SoftBody &a = bodies[c.a], &b = bodies[c.b];
      for (int k = 0; k < c.count; ++k) {
        SoftPoint& p = c.p[k];
        const double s = currentSeparation(a, b, c, p);
        double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
        if (s > 0.0) {
          bias = s / h;  // speculative: the gap may close within the substep, not more
        } else if (useBias) {
          bias = std::max(c.soft.biasRate * s, -settings::kContactPushMaxSpeed);
          massScale = c.soft.massScale;
          impulseScale = c.soft.impulseScale;
        }
        const double vn = c.n.dot(relativeVelocityAt(a, b, p));
        const double lambda = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
        const double total = std::max(p.normalImpulse + lambda, 0.0);
        applyAt(a, b, p, (total - p.normalImpulse) * c.n);
        p.normalImpulse = total;
      }
      if (c.friction <= 0.0) continue;
      const Vec2 t = tangentOf(c.n);
      for (int k = 0; k < c.count; ++k) solveFrictionAt(a, b, c.p[k], t, c.friction);
    }
  }

  // the separation now, from where the point's material points on A and B have moved
  double currentSeparation(const SoftBody& a, const SoftBody& b, const SoftContact& c, const SoftPoint& p) const {
    const Vec2 pa = a.x + rotations_[c.a].apply(p.localA), pb = b.x + rotations_[c.b].apply(p.localB);
    return p.separation + c.n.dot(pa - pb);
  }

  // restitution for points that arrived faster than the threshold and pushed (Box2D v3's
  // b2ApplyRestitution): the normal velocity brought to −e times the one before the step
  void applyRestitution(World& world) {
    std::vector<Body>& bodies = world.bodies;
    for (SoftContact& c : constraints_) {
      if (c.restitution == 0.0) continue;
      Body &a = bodies[c.a], &b = bodies[c.b];
      for (int k = 0; k < c.count; ++k) {
        SoftPoint& p = c.p[k];
        if (p.vnBefore > -settings::kRestitutionThreshold || p.totalNormalImpulse == 0.0) continue;
        const double vn = c.n.dot(relativeVelocityAt(a, b, p));
        const double lambda = -p.normalMass * (vn + c.restitution * p.vnBefore);
        const double total = std::max(p.normalImpulse + lambda, 0.0);
        applyAt(a, b, p, (total - p.normalImpulse) * c.n);
        p.totalNormalImpulse += total - p.normalImpulse;
        p.normalImpulse = total;
      }
    }
  }

  // the impulses kept for the next step's warm start, and the impacts of the step recorded
  void store(World& world, double t) {
    for (size_t i = 0; i < constraints_.size(); ++i) {
      const SoftContact& s = constraints_[i];
      Contact& c = world.contacts[i];
      for (int k = 0; k < s.count; ++k) {
        const SoftPoint& p = s.p[k];
        c.state[k].normalImpulse = p.normalImpulse;
        c.state[k].tangentImpulse = p.tangentImpulse;
        c.state[k].normalMass = p.normalMass;
        c.state[k].tangentMass = p.tangentMass;
        c.state[k].vnBefore = p.vnBefore;
        if (p.vnBefore >= -settings::kRestitutionThreshold || p.totalNormalImpulse <= 0.0) continue;
        const Vec2 r = c.manifold.points[k].point;
        ImpactRecord rec{t, s.a, s.b, r, s.n, p.totalNormalImpulse, p.tangentImpulse};
        rec.vnBefore = p.vnBefore;
        rec.vnAfter = s.n.dot(relativeVelocityAt(world.bodies[s.a], world.bodies[s.b], p));
        world.impacts.push_back(rec);
      }
    }
  }

  std::vector<SoftContact> constraints_;
  std::vector<Rot> rotations_;  // every body's orientation, after each substep's positions
  std::vector<SoftBody> bodies_;  // the bodies during the substeps
  States states_;                 // scratch of integrateVelocities
  std::vector<Contact> fresh_;    // the contacts found, then last step's (their storage reused)
  Rates rates_;
};

}  // namespace

std::unique_ptr<Method> makeSoftStepSolver() { return std::make_unique<SoftStepSolver>(); }

}  // namespace sim::world

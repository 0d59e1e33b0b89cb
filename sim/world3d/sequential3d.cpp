// The 3D `sequential` method: Box2D 2.4's solver (Catto, "Fast and Simple Physics using Sequential
// Impulses", GDC 2006) in 3D, as 2D's sequential_solver.cpp: contacts at the start of the step,
// warm started by feature (a box's corner), accumulated impulses clamped, Coulomb friction in the
// contact's plane held within the cone |j_t| ≤ μ j_n, restitution from the normal velocity before
// the solve above 1 m/s, a gap closed within the step only by a point that carried no load or a gap
// wider than the slop, then position passes (nonlinear Gauss–Seidel with slop). The contacts'
// velocity change moves the bodies as the integrator moves a constant force (2D: integratePositions).
#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/world3d/impulse3d.h"
#include "sim/world3d/world.h"

namespace sim::world3d {
namespace core_settings = sim::core::settings;

namespace {

// two unit directions spanning the contact's plane
void tangentsOf(const Vec3& n, Vec3& t1, Vec3& t2) {
  t1 = (std::abs(n.x()) < 0.57 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  t2 = n.cross(t1);
}

// one point of a contact, prepared once per step
struct SolverPoint3 {
  Vec3 r = Vec3::Zero();  // the world point at the step's start
  // from each center of mass to the point, at the step's start: the velocity loops run on the free
  // velocities with the lever arms where the contact was found (Catto 2006), not where the free
  // motion moved the centers
  Vec3 rA = Vec3::Zero(), rB = Vec3::Zero();
  Vec3 anchorA = Vec3::Zero(), anchorB = Vec3::Zero();  // body coordinates (B: world for a plane)
  double separation = 0.0;
  double normalMass = 0.0, tangentMass1 = 0.0, tangentMass2 = 0.0;
  double bias = 0.0;  // the lowest normal velocity allowed: restitution or a closing gap
  double vnBefore = 0.0;
  double normalImpulse = 0.0;
  double tangentImpulse1 = 0.0, tangentImpulse2 = 0.0;
};

struct SolverContact3 {
  const Contact3* contact = nullptr;
  Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
  PairInverses inv;  // the world inverse inertias at the step's start
  SolverPoint3 p[kMaxContactPoints];
};

// the same pair's point of the same feature last step, for the warm start
const ContactPoint3* previousPoint(const std::vector<Contact3>& previous, const Contact3& c, int feature) {
  for (const Contact3& old : previous)
    if (old.a == c.a && old.b == c.b)
      for (int k = 0; k < old.count; ++k)
        if (old.points[k].feature == feature) return &old.points[k];
  return nullptr;
}

// v_n of a point now
double normalVelocity(World& w, const Contact3& c, const Vec3& r) {
  return c.normal.dot(relativeVelocity(w.bodies[c.a], c.withPlane() ? nullptr : &w.bodies[c.b], r));
}

class SequentialSolver3 final : public Method3 {
 public:
  std::unique_ptr<Method3> clone() const override { return std::make_unique<SequentialSolver3>(*this); }

  // Box-Lite's World::Step in 3D: contacts, free motion, velocity iterations, positions, position
  // iterations
  void step(World& world, double start, double h) override {
    // the contacts where the bodies are now, carrying over last step's impulses, prepared
    std::vector<Contact3> previous = std::move(world.contacts);
    world.contacts = world.findContacts(core_settings::kContactMargin);
    prepare(world, previous, h);
    // move freely, remembering where the free motion ends
    moveFreely(world, start, h);
    const States free = world.states();
    // the contacts, prepared where the step began, solved on the free velocities
    warmStart(world);
    for (int k = 0; k < world.def().velocityIterations; ++k) solveVelocities(world);
    store(world);
    integratePositions(world, free, h);
    for (int k = 0; k < world.def().positionIterations; ++k)
      if (solvePositions(world)) break;
    recordImpacts(world, start + h);
  }

 private:
  Body* b(World& w, const SolverContact3& s) const { return s.contact->withPlane() ? nullptr : &w.bodies[s.contact->b]; }

  void prepare(World& world, const std::vector<Contact3>& previous, double h) {
    solver_.assign(world.contacts.size(), SolverContact3{});
    for (size_t i = 0; i < world.contacts.size(); ++i) {
      Contact3& c = world.contacts[i];
      SolverContact3& s = solver_[i];
      s.contact = &c;
      tangentsOf(c.normal, s.t1, s.t2);
      Body& a = world.bodies[c.a];
      Body* other = b(world, s);
      const PairInverses inv = s.inv = pairInverses(a, other);
      for (int k = 0; k < c.count; ++k) {
        const ContactPoint3& cp = c.points[k];
        SolverPoint3& p = s.p[k];
        p.r = cp.point;
        p.rA = cp.point - a.x;
        p.rB = other ? Vec3(cp.point - other->x) : Vec3::Zero();
        p.separation = cp.separation;
        p.anchorA = a.rotation().transpose() * (cp.point - a.x);
        p.anchorB = other ? Vec3(other->rotation().transpose() * (cp.point - other->x)) : cp.point;
        p.normalMass = 1.0 / inverseEffectiveMass(a, other, inv, cp.point, c.normal);
        p.tangentMass1 = 1.0 / inverseEffectiveMass(a, other, inv, cp.point, s.t1);
        p.tangentMass2 = 1.0 / inverseEffectiveMass(a, other, inv, cp.point, s.t2);
        if (const ContactPoint3* old = previousPoint(previous, c, cp.feature)) {
          p.normalImpulse = old->normalImpulse;
          // the old friction impulse, onto this step's tangents
          p.tangentImpulse1 = old->tangentImpulse.dot(s.t1), p.tangentImpulse2 = old->tangentImpulse.dot(s.t2);
        }
        const double vn = p.vnBefore = normalVelocity(world, c, cp.point);
        // restitution for a fast arrival within the step; slower ones settle; a gap may close
        // but not be overrun (2D's rule: a loaded point within the slop counts as touching)
        if (vn < -core_settings::kRestitutionThreshold && cp.separation + h * vn < 0.0) p.bias = -c.restitution * vn;
        else if (cp.separation > 0.0 && (p.normalImpulse == 0.0 || cp.separation > core_settings::kLinearSlop))
          p.bias = -cp.separation / h;
        else p.bias = 0.0;
      }
    }
  }

  // j to A at the point, −j to B, through the lever arms and inverses of the step's start
  void apply(World& w, const SolverContact3& s, const SolverPoint3& p, const Vec3& j) const {
    Body& a = w.bodies[s.contact->a];
    a.v += a.invMass * j;
    a.omega += s.inv.a * p.rA.cross(j);
    if (Body* other = b(w, s)) {
      other->v -= other->invMass * j;
      other->omega -= s.inv.b * p.rB.cross(j);
    }
  }
  // the velocity of A's material point relative to B's, by the same lever arms
  Vec3 velocityAt(World& w, const SolverContact3& s, const SolverPoint3& p) const {
    const Body& a = w.bodies[s.contact->a];
    Vec3 v = a.v + a.omega.cross(p.rA);
    if (const Body* other = b(w, s)) v -= other->v + other->omega.cross(p.rB);
    return v;
  }

  void warmStart(World& w) const {
    for (const SolverContact3& s : solver_)
      for (int k = 0; k < s.contact->count; ++k) {
        const SolverPoint3& p = s.p[k];
        apply(w, s, p, p.normalImpulse * s.contact->normal + p.tangentImpulse1 * s.t1 + p.tangentImpulse2 * s.t2);
      }
  }

  // one Gauss–Seidel sweep: each point's friction, then its normal impulse
  void solveVelocities(World& w) {
    for (SolverContact3& s : solver_) {
      const Contact3& c = *s.contact;
      for (int k = 0; k < c.count; ++k) {
        SolverPoint3& p = s.p[k];
        // Coulomb friction: the accumulated impulse in the contact's plane within μ times the normal one
        if (c.friction > 0.0) {
          const Vec3 v = velocityAt(w, s, p);
          const double want1 = p.tangentImpulse1 - p.tangentMass1 * s.t1.dot(v);
          const double want2 = p.tangentImpulse2 - p.tangentMass2 * s.t2.dot(v);
          const double limit = c.friction * p.normalImpulse, length = std::hypot(want1, want2);
          const double scale = length > limit && length > 0.0 ? limit / length : 1.0;
          const double new1 = scale * want1, new2 = scale * want2;
          apply(w, s, p, (new1 - p.tangentImpulse1) * s.t1 + (new2 - p.tangentImpulse2) * s.t2);
          p.tangentImpulse1 = new1, p.tangentImpulse2 = new2;
        }
        // the normal impulse pushes, never pulls
        const double lambda = -p.normalMass * (c.normal.dot(velocityAt(w, s, p)) - p.bias);
        const double total = std::max(p.normalImpulse + lambda, 0.0);
        apply(w, s, p, (total - p.normalImpulse) * c.normal);
        p.normalImpulse = total;
      }
    }
  }

  // the accumulated impulses back into the contacts, for the next step's warm start
  void store(World& w) const {
    for (const SolverContact3& s : solver_) {
      Contact3& c = w.contacts[static_cast<size_t>(s.contact - w.contacts.data())];
      for (int k = 0; k < c.count; ++k) {
        c.points[k].normalImpulse = s.p[k].normalImpulse;
        c.points[k].tangentImpulse = s.p[k].tangentImpulse1 * s.t1 + s.p[k].tangentImpulse2 * s.t2;
      }
    }
  }

  // the free motion plus what the contacts' velocity change moves the body: their impulse over the
  // step as a force held for the step, moved as the integrator moves a constant force (sim/README.md:
  // With contacts): h Δv under symplectic Euler, ½ h Δv under the midpoint rule, RK4 and the
  // splitting (x + h (v + h a/2) for a constant a), none under explicit Euler
  static void integratePositions(World& w, const States& free, double h) {
    const double reach = constantAccelerationWeight(w.def().integrator) * h;
    for (size_t i = 0; i < w.bodies.size(); ++i) {
      Body& body = w.bodies[i];
      body.x = free[i].x + reach * (body.v - free[i].v);
      body.q = (rotationQuaternion(reach * (body.omega - free[i].omega)) * free[i].q).normalized();
    }
  }

  // one pass of position correction at every point: the separation now, from its anchors, pushed
  // out to within the slop (Box2D's b2ContactSolver::SolvePositionConstraints); true when every point
  // is within three slops
  bool solvePositions(World& w) {
    double deepest = 0.0;
    for (SolverContact3& s : solver_) {
      const Contact3& c = *s.contact;
      Body& a = w.bodies[c.a];
      Body* other = b(w, s);
      for (int k = 0; k < c.count; ++k) {
        const SolverPoint3& p = s.p[k];
        const Vec3 pa = a.x + a.rotation() * p.anchorA;
        const Vec3 pb = other ? Vec3(other->x + other->rotation() * p.anchorB) : p.anchorB;
        // both anchors were at p.r when the step began: the separation has changed by n̂ · (pa − pb)
        const double now = p.separation + c.normal.dot(pa - pb);
        deepest = std::min(deepest, now);
        const double correction = std::clamp(core_settings::kPositionCorrection * (now + core_settings::kLinearSlop),
                                             -core_settings::kMaxLinearCorrection, 0.0);
        if (correction == 0.0) continue;
        const Vec3 r = 0.5 * (pa + pb);
        const PairInverses inv = pairInverses(a, other);
        const double kInv = inverseEffectiveMass(a, other, inv, r, c.normal);
        if (kInv == 0.0) continue;
        const Vec3 push = (-correction / kInv) * c.normal;
        a.x += a.invMass * push;
        a.q = (rotationQuaternion(inv.a * (r - a.x).cross(push)) * a.q).normalized();
        if (other) {
          other->x -= other->invMass * push;
          other->q = (rotationQuaternion(-(inv.b * (r - other->x).cross(push))) * other->q).normalized();
        }
      }
    }
    return deepest >= -core_settings::kPositionSolvedDepth;
  }

  // the impacts of the step: points that arrived faster than the restitution threshold
  void recordImpacts(World& w, double t) const {
    for (const SolverContact3& s : solver_) {
      const Contact3& c = *s.contact;
      for (int k = 0; k < c.count; ++k) {
        const SolverPoint3& p = s.p[k];
        if (p.vnBefore >= -core_settings::kRestitutionThreshold || p.normalImpulse <= 0.0) continue;
        ImpactRecord3 rec{t, c.a, c.b, p.r, c.normal, p.normalImpulse, p.tangentImpulse1 * s.t1 + p.tangentImpulse2 * s.t2};
        rec.vnBefore = p.vnBefore;
        rec.vnAfter = c.normal.dot(velocityAt(w, s, p));
        w.impacts.push_back(rec);
      }
    }
  }

  std::vector<SolverContact3> solver_;
};

}  // namespace

std::unique_ptr<Method3> makeSequentialSolver3() { return std::make_unique<SequentialSolver3>(); }

}  // namespace sim::world3d

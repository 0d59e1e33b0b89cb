// The `event` method: exact event-driven simulation. Within a step the bodies move to the
// earliest time of impact, the notes' impulse is applied there, and the motion goes on.
//
// - Between impacts the bodies move exactly when only gravity acts (x + vτ + ½gτ², θ + ωτ), and
//   otherwise by one integrator step of the length needed.
// - The time of impact of each pair whose swept boxes meet is found by conservative advancement
//   (Mirtich 1996; time_of_impact.h): nothing tunnels, at any speed.
// - Simultaneous impacts (a Newton's cradle, a box landing flat) are resolved by Gauss–Seidel
//   sweeps in a fixed order of pairs (by body index), each pair's approaching points solved
//   together, until nothing approaches: deterministic, momentum-conserving, and for a line of
//   equal balls it passes the momentum down the line.
// - A contact that leaves an impact slower than kRestingSpeed becomes resting contact: impacts
//   would otherwise pile up in finite time (Zeno). A resting contact pushes back with the force
//   that keeps it from sinking (acceleration-level complementarity, projected Gauss–Seidel) and
//   is released when the bodies move apart.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "sim/collision/broad_phase.h"
#include "sim/collision/compound.h"
#include "sim/collision/impulse.h"
#include "sim/collision/time_of_impact.h"
#include "sim/world/methods.h"
#include "sim/world/world.h"

namespace sim::world {
using sim::collision::Aabb;
using sim::collision::Manifold;
using namespace sim::core;
using namespace sim::collision;

namespace {

// a body under constant acceleration k for τ: exact
BodyState uniformlyAccelerated(const BodyState& s, const BodyRate& k, double tau) {
  BodyState y = s;
  y.x += tau * s.v + 0.5 * tau * tau * k.vDot;
  y.angle += tau * s.omega + 0.5 * tau * tau * k.omegaDot;
  y.v += tau * k.vDot;
  y.omega += tau * k.omegaDot;
  return y;
}

// pairs whose boxes, swept from `from` to `end` and grown by `touch`, meet: only they can collide
std::vector<std::pair<int, int>> sweptPairs(const World& world, const States& from, const States& end, double touch) {
  std::vector<Aabb> boxes;
  std::vector<bool> fixed;
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    Aabb box = bounds(b.shape, from[i].pose());
    const Aabb last = bounds(b.shape, end[i].pose());
    box.lower = box.lower.cwiseMin(last.lower) - Vec2::Constant(touch);
    box.upper = box.upper.cwiseMax(last.upper) + Vec2::Constant(touch);
    boxes.push_back(box);
    fixed.push_back(b.isStatic);
  }
  return overlappingPairs(boxes, fixed);
}

// the points of a contact approaching faster than round-off, as impact records at time t with
// their v_n⁻; how many
int approachingPoints(const World& world, const Contact& c, double t, ImpactRecord rec[2]) {
  const Body &a = world.bodies[c.a], &b = world.bodies[c.b];
  const Vec2 n = c.manifold.normal;
  double vn[2];
  int approaching[2], count = 0;
  for (int k = 0; k < c.manifold.count; ++k) {
    vn[k] = n.dot(relativeVelocity(a, b, c.manifold.points[k].point));
    if (vn[k] < -settings::kApproachFloor) approaching[count++] = k;
  }
  for (int m = 0; m < count; ++m) {
    const Vec2 r = c.manifold.points[approaching[m]].point;
    rec[m] = {t, c.a, c.b, r, n};
    rec[m].vnBefore = vn[approaching[m]];
  }
  return count;
}

// both points at once: the impulses (γ1, γ2) that give each v_n⁺ = −c_r v_n⁻ together; false
// when the two act as one or one of them would pull
bool resolveTogether(Body& a, Body& b, const Contact& c, ImpactRecord rec[2]) {
  const Vec2 n = c.manifold.normal, r1 = rec[0].point, r2 = rec[1].point;
  const NormalBlock K = normalBlock(a, b, r1, r2, n, inverseEffectiveMass(a, b, r1, n), inverseEffectiveMass(a, b, r2, n));
  const double d1 = -(1.0 + c.restitution) * rec[0].vnBefore, d2 = -(1.0 + c.restitution) * rec[1].vnBefore;
  if (!(K.det > settings::kMinBlockDeterminant * K.k11 * K.k22)) return false;
  const Vec2 gamma = K.solve(d1, d2);
  const double g1 = gamma.x(), g2 = gamma.y();
  if (!(g1 >= 0.0 && g2 >= 0.0)) return false;
  applyImpulsePair(a, b, r1, g1 * n);
  applyImpulsePair(a, b, r2, g2 * n);
  rec[0].impulse = g1, rec[1].impulse = g2;
  return true;
}

// the notes' impulse at a contact's approaching points (rec, count of them), logged; how many
// impulses it took
int resolveContact(World& world, const Contact& c, ImpactRecord rec[2], int count) {
  Body &a = world.bodies[c.a], &b = world.bodies[c.b];
  const Vec2 n = c.manifold.normal;
  if (!(count == 2 && c.friction == 0.0 && resolveTogether(a, b, c, rec))) {
    // one point: the one approaching fastest
    if (count == 2 && rec[1].vnBefore < rec[0].vnBefore) rec[0] = rec[1];
    count = 1;
    const ImpulseResult j = resolveImpact(a, b, rec[0].point, n, c.restitution, c.friction);
    rec[0].impulse = j.gamma;
    rec[0].tangentImpulse = j.tangent;
  }
  for (int m = 0; m < count; ++m) {
    rec[m].vnAfter = n.dot(relativeVelocity(a, b, rec[m].point));
    world.impacts.push_back(rec[m]);
  }
  return count;
}

// Gauss–Seidel sweeps over the touching contacts at time t, the notes' impulse at each
// approaching one, until nothing approaches
void sweepImpacts(World& world, const std::vector<Contact>& touching, double t) {
  for (int sweep = 0; sweep < settings::kMaxImpactSweeps; ++sweep) {
    bool any = false;
    for (const Contact& c : touching) {
      ImpactRecord rec[2];
      const int count = approachingPoints(world, c, t, rec);
      if (count == 0) continue;
      any = true;
      resolveContact(world, c, rec, count);
    }
    if (!any) break;
  }
}

// a pair of parts at rest on each other (a body of one shape is its own part 0): a body made of
// parts may rest on one part and strike with another
struct RestingPair {
  int a = 0, partA = 0, b = 0, partB = 0;
  bool operator==(const RestingPair&) const = default;
};
RestingPair restingPairOf(const Contact& c) { return {c.a, c.partA, c.b, c.partB}; }

// a row of the resting contacts' forces: one point, its normal, m_eff⁻¹ and the push λ
struct RestingRow {
  int a, b;
  Vec2 r, n;
  double k, lambda = 0.0;
};

class EventStepper final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<EventStepper>(*this); }

  // the event method advances to the instant of touching: it cannot start from an overlap
  void start(World& world) override {
    gravityOnly_ = world.def().forces.gravityOnly();
    for (const Contact& c : world.findContacts(0.0))
      if (c.manifold.separation < -settings::kTouchingTolerance * world.sceneSize())
        throw InitialOverlap(c.a, c.b, -c.manifold.separation);
  }

  // to the earliest time of impact within the rest of the step, the impulses of every impact at
  // that instant, and on, until the step's end
  void step(World& world, const TimeStep& step) override {
    double done = 0.0;  // how much of the step is done
    for (int impacts = 1;; ++impacts) {
      // resting contacts neither sink nor approach; ones that came apart are released
      holdRestingContacts(world);
      const States from = world.states();
      const double span = step.h - done;
      const std::optional<double> impact = earliestImpact(world, step, from, span);
      moveAlong(world, step, from, impact ? *impact : span);
      if (!impact) return;
      done += *impact;
      const double now = step.start + done;
      resolveImpactsAt(world, step, now);
      if (impacts > settings::kMaxImpactsPerStep) throw ImpactsPileUp(now, settings::kMaxImpactsPerStep);
    }
  }

  // contact forces of the resting pairs at state y: the smallest pushes that keep every resting
  // point from accelerating into the other body (projected Gauss–Seidel on the acceleration LCP)
  void addContactForces(const World& world, const States& y, std::vector<Vec2>& force,
                        std::vector<double>& torque) const override {
    if (restingPairs_.empty()) return;
    std::vector<RestingRow> rows = restingRows(world, y);
    solveRestingRows(world, y, force, torque, rows);
    for (const RestingRow& w : rows) {
      const Vec2 f = w.lambda * w.n;
      force[w.a] += f;
      torque[w.a] += cross(w.r - y[w.a].x, f);
      force[w.b] -= f;
      torque[w.b] -= cross(w.r - y[w.b].x, f);
    }
  }

 private:
  bool isResting(const RestingPair& p) const {
    return std::find(restingPairs_.begin(), restingPairs_.end(), p) != restingPairs_.end();
  }

  // a resting pair's manifold with its two parts where their bodies are at `pa` and `pb`
  static Manifold collideResting(const World& world, const RestingPair& p, const Pose& pa, const Pose& pb, double margin) {
    const Shape &a = world.bodies[p.a].shape, &b = world.bodies[p.b].shape;
    return collide(partShape(a, p.partA), partPoseOf(a, p.partA, pa), partShape(b, p.partB), partPoseOf(b, p.partB, pb), margin);
  }

  // where the bodies are after τ of motion from `from`
  States motion(const World& world, const TimeStep& step, const States& from, double tau) const {
    States y = from;
    if (tau == 0.0) return y;
    const StepDynamics dynamics(world, step);
    if (gravityOnly_) {
      // constant accelerations (gravity, and resting contacts' forces at this instant): exact
      Rates k;
      dynamics.rates(step.start, from, k);
      for (size_t i = 0; i < y.size(); ++i) y[i] = uniformlyAccelerated(from[i], k[i], tau);
      return y;
    }
    integrate(world.def().integrator, dynamics, step.start, tau, y);
    return y;
  }

  void moveAlong(World& world, const TimeStep& step, const States& from, double tau) const {
    world.setStates(motion(world, step, from, tau));
  }

  // the first time of impact of any pair within `span` from `from`, or none
  std::optional<double> earliestImpact(const World& world, const TimeStep& step, const States& from, double span) const {
    if (span <= 0.0) return std::nullopt;
    const States end = motion(world, step, from, span);
    const double tol = settings::kImpactTolerance * world.sceneSize();
    const double touch = settings::kTouchingTolerance * world.sceneSize();
    // under constant forces each body moves on its own parabola: no need to move the others
    Rates k0;
    if (gravityOnly_) StepDynamics(world, step).rates(step.start, from, k0);
    std::optional<double> first;
    double horizon = span;
    for (const std::pair<int, int>& pair : sweptPairs(world, from, end, touch)) {
      // plain ints, not structured bindings: the motion lambda captures them, which C++20 allows
      // and clang 14 does not
      const int i = pair.first, j = pair.second;
      const Shape &bodyA = world.bodies[i].shape, &bodyB = world.bodies[j].shape;
      // no point of either body approaches faster than this (the whole body's reach: a part turns
      // about its body's center of mass)
      const double margin = gravityOnly_ ? 1.0 : settings::kApproachBoundMargin;
      const double bound =
          margin * std::max(approachBound(bodyA, from[i], bodyB, from[j]), approachBound(bodyA, end[i], bodyB, end[j]));
      // each pair of parts not at rest on each other (a body of one shape is its own part)
      for (int pa = 0; pa < partCount(bodyA); ++pa)
        for (int pb = 0; pb < partCount(bodyB); ++pb) {
          if (isResting({i, pa, j, pb})) continue;
          ToiInput in;
          in.a = &partShape(bodyA, pa), in.b = &partShape(bodyB, pb);
          in.motion = [&, i, j, pa, pb](double tau) -> PosePair {
            if (gravityOnly_)
              return {partPoseOf(bodyA, pa, uniformlyAccelerated(from[i], k0[i], tau).pose()),
                      partPoseOf(bodyB, pb, uniformlyAccelerated(from[j], k0[j], tau).pose())};
            const States y = motion(world, step, from, tau);
            return {partPoseOf(bodyA, pa, y[i].pose()), partPoseOf(bodyB, pb, y[j].pose())};
          };
          in.approachBound = bound;
          in.horizon = horizon, in.span = span, in.tolerance = tol, in.touching = touch;
          // a later pair searches only up to the earliest impact found so far
          if (const std::optional<double> tau = timeOfImpact(in)) first = horizon = *tau;
        }
    }
    return first;
  }

  // every impact at time t, then the contacts that came to rest
  void resolveImpactsAt(World& world, const TimeStep& step, double t) {
    const double touch = settings::kTouchingTolerance * world.sceneSize();
    std::vector<Contact> touching = world.findContacts(touch);
    std::erase_if(touching, [&](const Contact& c) { return isResting(restingPairOf(c)); });
    sweepImpacts(world, touching, t);
    restSlowContacts(world, step, touching, t);
  }

  // a contact pressed together that moves too slowly to ever get clear of the next impact rests
  // instead: the bounces left would pile up in finite time (Zeno). Pressed means that over one
  // step of free motion (forces, spin, and the contact forces of what already rests) the two
  // would overlap.
  void restSlowContacts(World& world, const TimeStep& step, const std::vector<Contact>& touching, double t) {
    const double touch = settings::kTouchingTolerance * world.sceneSize();
    for (const Contact& c : touching) {
      if (isResting(restingPairOf(c))) continue;
      Body &a = world.bodies[c.a], &b = world.bodies[c.b];
      const Vec2 n = c.manifold.normal;
      double fastest = 0.0;
      for (int k = 0; k < c.manifold.count; ++k)
        fastest = std::max(fastest, std::abs(n.dot(relativeVelocity(a, b, c.manifold.points[k].point))));
      if (fastest > settings::kRestingSpeed) continue;
      const States ahead = motion(world, step, world.states(), world.def().dt);
      const double gap = collideResting(world, restingPairOf(c), ahead[c.a].pose(), ahead[c.b].pose(), 0.0).separation;
      if (gap >= -touch) continue;
      // the rest of the geometric series of bounces is below kRestingSpeed: end it here
      for (int k = 0; k < c.manifold.count; ++k) {
        const Vec2 r = c.manifold.points[k].point;
        const double vn = n.dot(relativeVelocity(a, b, r));
        if (vn != 0.0) applyImpulsePair(a, b, r, (-vn / inverseEffectiveMass(a, b, r, n)) * n);
      }
      restingPairs_.push_back(restingPairOf(c));
      // still moving: any point of either body faster than the resting speed
      const auto moves = [](const Body& body) {
        return !body.isStatic && body.v.norm() + std::abs(body.omega) * boundingRadius(body.shape) > settings::kRestingSpeed;
      };
      world.resting.push_back({t, c.a, c.b, moves(a) || moves(b)});
    }
  }

  // resting contacts neither sink in nor approach; the pairs that came apart are released
  void holdRestingContacts(World& world) {
    const double touch = settings::kTouchingTolerance * world.sceneSize();
    std::erase_if(restingPairs_, [&](const RestingPair& p) {
      Body &a = world.bodies[p.a], &b = world.bodies[p.b];
      const Manifold m = collideResting(world, p, a.pose(), b.pose(), settings::kRestingReach * touch);
      if (m.count == 0) return true;  // they came apart
      bool separating = true;
      for (int k = 0; k < m.count; ++k) {
        const Vec2 r = m.points[k].point;
        // no sinking in: remove round-off overlap and approach without restitution
        if (m.points[k].separation < 0.0) {
          const double share = a.invMass + b.invMass;
          a.x -= (m.points[k].separation * a.invMass / share) * m.normal;
          b.x += (m.points[k].separation * b.invMass / share) * m.normal;
        }
        if (m.normal.dot(relativeVelocity(a, b, r)) < 0.0) resolveImpact(a, b, r, m.normal, 0.0, 0.0);
        if (m.normal.dot(relativeVelocity(a, b, r)) <= settings::kRestingSpeed) separating = false;
      }
      return separating;
    });
  }

  // one row per point of every resting pair at state y
  std::vector<RestingRow> restingRows(const World& world, const States& y) const {
    std::vector<RestingRow> rows;
    for (const RestingPair& p : restingPairs_) {
      const int i = p.a, j = p.b;
      const Manifold m = collideResting(world, p, y[i].pose(), y[j].pose(),
                                        settings::kRestingReach * settings::kTouchingTolerance * world.sceneSize());
      for (int k = 0; k < m.count; ++k) {
        Body a = world.bodies[i], b = world.bodies[j];
        a.x = y[i].x, b.x = y[j].x;
        rows.push_back({i, j, m.points[k].point, m.normal, inverseEffectiveMass(a, b, m.points[k].point, m.normal)});
      }
    }
    return rows;
  }

  // the pushes λ ≥ 0 of the rows, by projected Gauss–Seidel: each row's relative normal
  // acceleration brought to zero, or its push to zero where it would pull
  static void solveRestingRows(const World& world, const States& y, const std::vector<Vec2>& force,
                               const std::vector<double>& torque, std::vector<RestingRow>& rows) {
    const std::vector<Body>& bodies = world.bodies;
    std::vector<Vec2> acc(y.size());
    std::vector<double> alpha(y.size());
    for (size_t i = 0; i < y.size(); ++i) {
      acc[i] = bodies[i].invMass * force[i];
      alpha[i] = bodies[i].invInertia * torque[i];
    }
    // relative normal acceleration of a row's two material points, centripetal terms included
    auto normalAcceleration = [&](const RestingRow& w) {
      const Vec2 ra = w.r - y[w.a].x, rb = w.r - y[w.b].x;
      const Vec2 aa = acc[w.a] + cross(alpha[w.a], ra) - y[w.a].omega * y[w.a].omega * ra;
      const Vec2 ab = acc[w.b] + cross(alpha[w.b], rb) - y[w.b].omega * y[w.b].omega * rb;
      return w.n.dot(aa - ab);
    };
    for (int sweep = 0; sweep < settings::kRestingForceSweeps; ++sweep)
      for (RestingRow& w : rows) {
        if (w.k == 0.0) continue;
        const double total = std::max(w.lambda - normalAcceleration(w) / w.k, 0.0);
        const Vec2 f = (total - w.lambda) * w.n;
        w.lambda = total;
        const Body &a = bodies[w.a], &b = bodies[w.b];
        acc[w.a] += a.invMass * f;
        alpha[w.a] += a.invInertia * cross(w.r - y[w.a].x, f);
        acc[w.b] -= b.invMass * f;
        alpha[w.b] -= b.invInertia * cross(w.r - y[w.b].x, f);
      }
  }

  bool gravityOnly_ = true;                // bodies move on exact parabolas
  std::vector<RestingPair> restingPairs_;  // contacts held at rest (Zeno), pair of parts by pair of parts
};

}  // namespace

std::unique_ptr<Method> makeEventStepper() { return std::make_unique<EventStepper>(); }

}  // namespace sim::world

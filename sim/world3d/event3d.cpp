// The 3D `event` method: exact isolated impacts, as 2D's event_stepper.cpp. Within a step the bodies
// move to the earliest time a body meets a plane or two spheres meet, the notes' impulse is applied
// there to every approaching point (the points of one pair that strike together, a box landing
// flat, solved together: each gets v_n⁺ = −c_r v_n⁻), and the motion goes on.
//
// - The time of impact of a pair is where its lowest separation, along the motion the integrator
//   gives over τ, crosses zero: the Illinois variant of regula falsi, to 1e-12 of the scene's size.
//   A gap that opens and closes again within one step is not seen.
// - A contact that leaves its impacts slower than kRestingSpeed while pressed together would
//   bounce ever faster (Zeno): 3D's event method does not hold resting contact, so it stops there
//   (ContactPersists); under `auto`, sequential redoes the step and goes on.
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "sim/world3d/collide3d.h"
#include "sim/world3d/impulse3d.h"
#include "sim/world3d/world.h"

namespace sim::world3d {
namespace core_settings = sim::core::settings;

namespace {

// the lowest separation of a pair (b < 0: a plane) at the states y
double gap(const World& world, int a, int b, const States& y) {
  const Body& body = world.bodies[a];
  if (b >= 0) return (y[a].x - y[b].x).norm() - body.shape.radius - world.bodies[b].shape.radius;
  ContactPoint3 points[kMaxContactPoints];
  const int count = planeContact(body.shape, y[a], world.def().planes[-1 - b], std::numeric_limits<double>::infinity(), points);
  double lowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) lowest = std::min(lowest, points[k].separation);
  return lowest;
}

// the pairs that can meet: every body with every plane, and every two spheres
std::vector<std::pair<int, int>> candidatePairs(const World& world) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(world.bodies.size());
  for (int i = 0; i < n; ++i) {
    for (int p = 0; p < static_cast<int>(world.def().planes.size()); ++p) pairs.emplace_back(i, -1 - p);
    if (world.bodies[i].shape.kind != ShapeKind::Sphere) continue;
    for (int j = i + 1; j < n; ++j)
      if (world.bodies[j].shape.kind == ShapeKind::Sphere) pairs.emplace_back(i, j);
  }
  return pairs;
}

Body* bodyB(World& world, const Contact3& c) { return c.withPlane() ? nullptr : &world.bodies[c.b]; }

// the approaching points of a contact now, as impact records at t with their v_n⁻; how many
int approachingPoints(World& world, const Contact3& c, double t, ImpactRecord3 rec[kMaxContactPoints]) {
  int count = 0;
  for (int k = 0; k < c.count; ++k) {
    const Vec3 r = c.points[k].point;
    const double vn = c.normal.dot(relativeVelocity(world.bodies[c.a], bodyB(world, c), r));
    if (vn >= -core_settings::kApproachFloor) continue;
    rec[count] = ImpactRecord3{t, c.a, c.b, r, c.normal};
    rec[count++].vnBefore = vn;
  }
  return count;
}

// the points that strike together, solved together: K γ = −(1 + c_r) v_n⁻ with K_ij the normal
// velocity at point i per unit impulse at point j (K's least-norm solution: four corners of a face
// are three degrees of freedom); false when one of them would pull or the system has no solution
bool resolveTogether(World& world, const Contact3& c, ImpactRecord3 rec[], int count) {
  Body& a = world.bodies[c.a];
  Body* b = bodyB(world, c);
  const PairInverses inv = pairInverses(a, b);
  const Vec3 n = c.normal;
  Eigen::MatrixXd k(count, count);
  Eigen::VectorXd rhs(count);
  for (int i = 0; i < count; ++i) {
    const Vec3 ra = rec[i].point - a.x;
    rhs(i) = -(1.0 + c.restitution) * rec[i].vnBefore;
    for (int j = 0; j < count; ++j) {
      const Vec3 rja = rec[j].point - a.x;
      double kij = a.invMass + n.dot((inv.a * rja.cross(n)).cross(ra));
      if (b) {
        const Vec3 rib = rec[i].point - b->x, rjb = rec[j].point - b->x;
        kij += b->invMass + n.dot((inv.b * rjb.cross(n)).cross(rib));
      }
      k(i, j) = kij;
    }
  }
  const Eigen::VectorXd gamma = k.completeOrthogonalDecomposition().solve(rhs);
  if (!gamma.allFinite() || (k * gamma - rhs).norm() > 1e-9 * rhs.norm() || gamma.minCoeff() < -1e-12 * gamma.maxCoeff())
    return false;
  for (int i = 0; i < count; ++i) applyImpulsePair(a, b, rec[i].point, std::max(gamma(i), 0.0) * n);
  for (int i = 0; i < count; ++i) rec[i].impulse = std::max(gamma(i), 0.0);
  return true;
}

// the friction of points struck together: one impulse at their γ-weighted centre, against the
// sliding there, within μ Σγ (the cone of the whole patch), so that a box landing flat while it
// slides is stopped alike at every corner, whatever order the corners are listed in
void frictionTogether(World& world, const Contact3& c, ImpactRecord3 rec[], int count) {
  double total = 0.0;
  Vec3 centre = Vec3::Zero();
  for (int i = 0; i < count; ++i) total += rec[i].impulse, centre += rec[i].impulse * rec[i].point;
  if (c.friction <= 0.0 || total <= 0.0) return;
  centre /= total;
  Body& a = world.bodies[c.a];
  Body* b = bodyB(world, c);
  const Vec3 v = relativeVelocity(a, b, centre);
  const Vec3 slide = v - c.normal.dot(v) * c.normal;
  const double speed = slide.norm();
  if (speed == 0.0) return;
  const Vec3 t = slide / speed;
  const double stop = speed / inverseEffectiveMass(a, b, pairInverses(a, b), centre, t);
  const Vec3 j = -std::min(stop, c.friction * total) * t;
  applyImpulsePair(a, b, centre, j);
  // logged and drawn at the points, each its share
  for (int i = 0; i < count; ++i) rec[i].tangentImpulse = rec[i].impulse / total * j;
}

// the notes' impulse at a contact's approaching points, logged
void resolveContact(World& world, const Contact3& c, ImpactRecord3 rec[], int count) {
  Body& a = world.bodies[c.a];
  Body* b = bodyB(world, c);
  const bool together = count >= 2 && resolveTogether(world, c, rec, count);
  if (together) frictionTogether(world, c, rec, count);
  if (!together) {
    // one point: the one approaching fastest
    int fastest = 0;
    for (int i = 1; i < count; ++i)
      if (rec[i].vnBefore < rec[fastest].vnBefore) fastest = i;
    rec[0] = rec[fastest];
    count = 1;
    const ImpulseResult3 j = resolveImpact(a, b, rec[0].point, c.normal, c.restitution, c.friction);
    rec[0].impulse = j.gamma;
    rec[0].tangentImpulse = j.tangent;
  }
  for (int i = 0; i < count; ++i) {
    rec[i].vnAfter = c.normal.dot(relativeVelocity(a, b, rec[i].point));
    world.impacts.push_back(rec[i]);
  }
}

class EventStepper3 final : public Method3 {
 public:
  std::unique_ptr<Method3> clone() const override { return std::make_unique<EventStepper3>(*this); }

  // the event method advances to the instant of touching: it cannot start from an overlap
  void start(World& world) override {
    for (const Contact3& c : world.findContacts(0.0))
      for (int k = 0; k < c.count; ++k)
        if (c.points[k].separation < -core_settings::kTouchingTolerance * world.sceneSize())
          throw ContactPersists(0.0, c.a, c.b, "bodies overlap at the start; the event method starts from separated bodies");
  }

  // to the earliest time of impact within the rest of the step, the impulses there, and on
  void step(World& world, double start, double h) override {
    double done = 0.0;
    for (int impacts = 1;; ++impacts) {
      const States from = world.states();
      const double span = h - done;
      const std::optional<double> tau = earliestImpact(world, from, start, h, span);
      world.setStates(motion(world, from, start, h, tau ? *tau : span));
      if (!tau) return;
      done += *tau;
      resolveImpactsAt(world, start, h, start + done);
      if (impacts > core_settings::kMaxImpactsPerStep)
        throw ContactPersists(start + done, -1, -1, "more than 10000 impacts in one step: impacts pile up");
    }
  }

 private:
  // the first time of impact of any pair within `span` from `from`, or none
  std::optional<double> earliestImpact(const World& world, const States& from, double start, double h, double span) const {
    if (span <= 0.0) return std::nullopt;
    const double touch = core_settings::kTouchingTolerance * world.sceneSize();
    const double tolerance = core_settings::kImpactTolerance * world.sceneSize();
    std::optional<double> first;
    double horizon = span;
    // the states at the earliest impact found so far, moved once each time it moves: the test below
    // of every pair against them stays a distance, not a motion of every body
    States atHorizon = motion(world, from, start, h, span);
    double movedTo = span;
    for (const std::pair<int, int>& pair : candidatePairs(world)) {
      // (named, not bound: a lambda may not capture a structured binding before C++20's clang 16)
      const int a = pair.first, b = pair.second;
      const auto g = [&](double tau) { return gap(world, a, b, motion(world, from, start, h, tau)); };
      if (movedTo != horizon) atHorizon = motion(world, from, start, h, horizon), movedTo = horizon;
      // only a pair that overlaps by the earliest impact found so far meets before it
      const double ghorizon = gap(world, a, b, atHorizon);
      if (!(ghorizon < 0.0)) continue;
      // out of a touching contact first, as 2D's leaveTouching: a look-ahead doubled until the pair
      // clears the band (then the crossing lies beyond), comes back in past the tolerance (then it
      // lies since the last probe: a pair touching and approaching strikes at once), or stays in the
      // band to the horizon (no impact: it is resting, not striking)
      double lo = 0.0, glo = gap(world, a, b, from);
      double hi = horizon, ghi = ghorizon;
      if (glo <= touch) {
        bool inBand = true;
        for (double ahead = core_settings::kLookAheadStart * span, last = 0.0, glast = std::max(glo, 0.0);; ahead *= 2.0) {
          ahead = std::min(ahead, horizon);
          const double gahead = g(ahead);
          if (gahead < -tolerance) {
            lo = last, glo = glast, hi = ahead, ghi = gahead;
            break;
          }
          if (gahead > touch) {
            lo = ahead, glo = gahead;
            break;
          }
          if (ahead >= horizon) {
            inBand = false;
            break;
          }
          last = ahead, glast = std::max(gahead, 0.0);
        }
        if (!inBand) continue;
      }
      // the crossing of zero in (lo, hi]: regula falsi, Illinois variant, kept on the near side
      int side = 0;
      for (int it = 0; it < core_settings::kMaxRefineIterations && glo > tolerance && hi - lo > core_settings::kImpactBracket * h;
           ++it) {
        const double mid = std::clamp(lo + (hi - lo) * glo / (glo - ghi), lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo));
        const double gm = g(mid);
        if (gm < 0.0) {
          hi = mid, ghi = gm;
          if (side == -1) glo *= 0.5;
          side = -1;
        } else {
          lo = mid, glo = gm;
          if (side == 1) ghi *= 0.5;
          side = 1;
        }
      }
      first = horizon = lo;
    }
    return first;
  }

  // every impact at time t, by Gauss–Seidel sweeps over the touching contacts until nothing
  // approaches; then a contact too slow to part, pressed together, is one that persists
  void resolveImpactsAt(World& world, double start, double h, double t) {
    const double touch = core_settings::kTouchingTolerance * world.sceneSize();
    const std::vector<Contact3> touching = world.findContacts(touch);
    for (int sweep = 0; sweep < core_settings::kMaxImpactSweeps; ++sweep) {
      bool any = false;
      for (const Contact3& c : touching) {
        ImpactRecord3 rec[kMaxContactPoints];
        const int count = approachingPoints(world, c, t, rec);
        if (count == 0) continue;
        any = true;
        resolveContact(world, c, rec, count);
      }
      if (!any) break;
    }
    // a step of free motion from here, once for every contact below
    const States ahead = motion(world, world.states(), start, h, world.def().dt);
    for (const Contact3& c : touching) {
      double fastest = 0.0;
      for (int k = 0; k < c.count; ++k)
        fastest =
            std::max(fastest, std::abs(c.normal.dot(relativeVelocity(world.bodies[c.a], bodyB(world, c), c.points[k].point))));
      if (fastest > core_settings::kRestingSpeed) continue;
      // pressed: a step of free motion would make them overlap
      if (gap(world, c.a, c.b, ahead) >= -touch) continue;
      throw ContactPersists(t, c.a, c.b, "a contact too slow to part persists (it would come to rest)");
    }
  }
};

}  // namespace

std::unique_ptr<Method3> makeEventStepper3() { return std::make_unique<EventStepper3>(); }

}  // namespace sim::world3d

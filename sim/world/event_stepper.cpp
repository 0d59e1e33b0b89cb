// The `event` method: exact event-driven simulation. Within a step the bodies move to the
// earliest time of impact, the notes' impulse is applied there, and the motion goes on.
//
// - Between impacts the bodies move exactly when only gravity acts (x + vτ + ½gτ², θ + ωτ), and
//   otherwise by one integrator step of the length needed.
// - The time of impact of a pair is found by conservative advancement (Mirtich 1996): the gap s
//   is a lower bound of the distance and no material point approaches faster than
//   |v_a − v_b| + |ω_a| R_a + |ω_b| R_b, so advancing by s over that bound never passes a
//   contact: nothing tunnels, at any speed. A secant probe brackets the root early and
//   regula falsi (Illinois) polishes it to kImpactTolerance of the scene's size, from the side
//   where the bodies do not overlap.
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
#include <limits>
#include <stdexcept>

#include "sim/collision/broad_phase.h"
#include "sim/collision/impulse.h"
#include "sim/world/world.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

struct World::Impact {
  bool found = false;
  double tau = 0.0;
};

namespace {

constexpr int kMaxSearchIterations = 100000;

// approaching slower than this, m/s, does not count as an impact (round-off after an impulse)
constexpr double kApproachFloor = 1e-3 * settings::kRestingSpeed;


bool isResting(const std::vector<std::pair<int, int>>& resting, int a, int b) {
  return std::find(resting.begin(), resting.end(), std::make_pair(a, b)) != resting.end();
}

Pose poseOf(const BodyState& s) { return {s.x, Rot::fromAngle(s.angle)}; }

// the fastest any point of the pair can approach the other, for conservative advancement
double approachBound(const Body& a, const Body& b, const BodyState& sa, const BodyState& sb) {
  double bound = (sa.v - sb.v).norm();
  if (sa.omega != 0.0) bound += std::abs(sa.omega) * boundingRadius(a.shape);
  if (sb.omega != 0.0) bound += std::abs(sb.omega) * boundingRadius(b.shape);
  return bound;
}

}  // namespace

void World::stepEvent(double h) {
  double done = 0.0;
  int count = 0;
  now_ = time;
  States from(bodies.size());
  while (true) {
    // resting contacts neither sink nor approach; ones that came apart are released
    holdRestingContacts();
    for (size_t i = 0; i < bodies.size(); ++i) from[i] = bodies[i].state();
    const double span = h - done;
    const Impact impact = earliestImpact(from, span);
    const double tau = impact.found ? impact.tau : span;
    moveAlong(from, tau);
    done = impact.found ? done + tau : h;
    now_ = time + done;
    if (!impact.found) break;
    resolveImpactsAt(now_);
    if (++count > settings::kMaxImpactsPerStep)
      throw std::runtime_error("more than " + std::to_string(settings::kMaxImpactsPerStep) +
                               " impacts in one step at t = " + std::to_string(now_) +
                               ": impacts pile up; use --collisions sequential");
  }
}

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

}  // namespace

// where the bodies are after τ of motion from `from`
States World::motion(const States& from, double tau) const {
  States y = from;
  if (tau == 0.0) return y;
  if (constantForces_) {
    // constant accelerations (gravity, and resting contacts' forces at this instant): exact
    Rates k;
    rates(time, from, k);
    for (size_t i = 0; i < y.size(); ++i) y[i] = uniformlyAccelerated(from[i], k[i], tau);
    return y;
  }
  integrate(integrator, *this, time, tau, y);
  return y;
}

void World::moveAlong(const States& from, double tau) {
  const States y = motion(from, tau);
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].isStatic) bodies[i].setState(y[i]);
}

World::Impact World::earliestImpact(const States& from, double span) const {
  Impact best;
  if (span <= 0.0) return best;
  const States end = motion(from, span);
  const double tol = settings::kImpactTolerance * sceneSize_;
  const double touch = settings::kTouchingTolerance * sceneSize_;

  // only pairs whose boxes swept over the span meet can collide
  std::vector<Aabb> boxes;
  std::vector<bool> fixed;
  for (size_t i = 0; i < bodies.size(); ++i) {
    Aabb box = bounds(bodies[i].shape, poseOf(from[i]));
    const Aabb last = bounds(bodies[i].shape, poseOf(end[i]));
    box.lower = box.lower.cwiseMin(last.lower) - Vec2::Constant(touch);
    box.upper = box.upper.cwiseMax(last.upper) + Vec2::Constant(touch);
    boxes.push_back(box);
    fixed.push_back(bodies[i].isStatic);
  }
  // under constant forces each body moves on its own parabola: no need to move the others
  Rates k0;
  if (constantForces_) rates(time, from, k0);
  double horizon = span;
  for (const auto& [i, j] : overlappingPairs(boxes, fixed)) {
    if (isResting(restingPairs_, i, j)) continue;
    const Body &a = bodies[i], &b = bodies[j];
    auto gap = [&](double tau) {
      if (constantForces_)
        return collide(a.shape, poseOf(uniformlyAccelerated(from[i], k0[i], tau)), b.shape,
                       poseOf(uniformlyAccelerated(from[j], k0[j], tau)), 0.0)
            .separation;
      const States y = motion(from, tau);
      return collide(a.shape, poseOf(y[i]), b.shape, poseOf(y[j]), 0.0).separation;
    };
    const double safety = constantForces_ ? 1.0 : 1.25;
    const double bound =
        safety * std::max(approachBound(a, b, from[i], from[j]), approachBound(a, b, end[i], end[j]));
    if (bound == 0.0) continue;

    // regula falsi (Illinois) between lo (gap ≥ 0) and hi (overlap), ending on the gap side
    auto refine = [&](double lo, double slo, double hi, double shi) {
      for (int k = 0; k < 200 && slo > tol && hi - lo > 1e-15 * span; ++k) {
        const double mid = std::clamp(lo + (hi - lo) * slo / (slo - shi), lo, hi);
        const double s = gap(mid);
        if (s >= 0.0) lo = mid, slo = s, shi *= 0.5;
        else hi = mid, shi = s, slo *= 0.5;
        if (s >= 0.0 && s <= tol) return mid;
      }
      return lo;
    };

    double tau = 0.0, s = gap(0.0);
    bool found = false;
    if (s <= touch) {
      // touching and not approaching (impacts at this instant are already resolved): look for
      // the moment the pair is clear of the touching band, doubling the look-ahead
      double ahead = 1e-12 * span, last = 0.0, sLast = std::max(s, 0.0);
      while (true) {
        ahead = std::min(ahead, horizon);
        const double sa = gap(ahead);
        if (sa < -tol) {  // it came back in: an impact inside (last, ahead)
          tau = refine(last, sLast, ahead, sa);
          found = true;
          break;
        }
        if (sa > touch || ahead >= horizon) {
          tau = ahead, s = sa;
          break;
        }
        last = ahead, sLast = std::max(sa, 0.0);
        ahead *= 2.0;
      }
      if (!found && (tau >= horizon)) continue;
    }
    // conservative advancement, with a secant probe to bracket the root early
    double prevTau = -1.0, prevS = 0.0;
    for (int k = 0; !found && k < kMaxSearchIterations; ++k) {
      if (s <= tol) {
        found = true;
        break;
      }
      const double advance = s / bound;
      if (prevTau >= 0.0 && prevS > s) {
        const double probe = tau + s * (tau - prevTau) / (prevS - s);
        if (probe > tau + advance && probe < horizon) {
          const double sp = gap(probe);
          if (sp < 0.0) {
            tau = refine(tau, s, probe, sp);
            found = true;
            break;
          }
        }
      }
      prevTau = tau, prevS = s;
      tau += advance;
      if (tau > horizon) break;
      s = gap(tau);
    }
    if (found && tau <= horizon) {
      best = {true, tau};
      horizon = tau;
    }
  }
  return best;
}

void World::resolveImpactsAt(double t) {
  const double touch = settings::kTouchingTolerance * sceneSize_;
  std::vector<Contact> touching = findContacts(touch);
  std::erase_if(touching, [&](const Contact& c) { return isResting(restingPairs_, c.a, c.b); });
  for (int sweep = 0; sweep < 1000; ++sweep) {
    bool any = false;
    for (const Contact& c : touching) {
      Body &a = bodies[c.a], &b = bodies[c.b];
      const Vec2 n = c.manifold.normal;
      double vn[2];
      int approaching[2], count = 0;
      for (int k = 0; k < c.manifold.count; ++k) {
        vn[k] = n.dot(relativeVelocity(a, b, c.manifold.points[k].point));
        if (vn[k] < -kApproachFloor) approaching[count++] = k;
      }
      if (count == 0) continue;
      any = true;
      ImpactRecord rec[2];
      for (int m = 0; m < count; ++m) {
        const Vec2 r = c.manifold.points[approaching[m]].point;
        rec[m] = {t, c.a, c.b, r, n};
        rec[m].vnBefore = vn[approaching[m]];
      }
      bool done = false;
      if (count == 2 && c.friction == 0.0) {
        // both points at once: the impulses (γ1, γ2) that give each v_n⁺ = −c_r v_n⁻ together
        const Vec2 r1 = rec[0].point, r2 = rec[1].point;
        const double ra1 = cross(r1 - a.x, n), ra2 = cross(r2 - a.x, n);
        const double rb1 = cross(r1 - b.x, n), rb2 = cross(r2 - b.x, n);
        const double k11 = inverseEffectiveMass(a, b, r1, n), k22 = inverseEffectiveMass(a, b, r2, n);
        const double k12 = a.invMass + b.invMass + a.invInertia * ra1 * ra2 + b.invInertia * rb1 * rb2;
        const double det = k11 * k22 - k12 * k12;
        const double d1 = -(1.0 + c.restitution) * rec[0].vnBefore, d2 = -(1.0 + c.restitution) * rec[1].vnBefore;
        if (det > 1e-12 * k11 * k22) {
          const double g1 = (k22 * d1 - k12 * d2) / det, g2 = (k11 * d2 - k12 * d1) / det;
          if (g1 >= 0.0 && g2 >= 0.0) {
            applyImpulsePair(a, b, r1, g1 * n);
            applyImpulsePair(a, b, r2, g2 * n);
            rec[0].impulse = g1, rec[1].impulse = g2;
            done = true;
          }
        }
      }
      if (!done) {
        // one point: the one approaching fastest
        if (count == 2 && rec[1].vnBefore < rec[0].vnBefore) rec[0] = rec[1];
        count = 1;
        const ImpulseResult j = resolveImpact(a, b, rec[0].point, n, c.restitution, c.friction);
        rec[0].impulse = j.gamma;
        rec[0].tangentImpulse = j.tangent;
      }
      for (int m = 0; m < count; ++m) {
        rec[m].vnAfter = n.dot(relativeVelocity(a, b, rec[m].point));
        impacts.push_back(rec[m]);
      }
    }
    if (!any) break;
  }
  // a contact pressed together that moves too slowly to ever get clear of the next impact rests
  // instead: the bounces left would pile up in finite time (Zeno). Pressed means that over one
  // step of free motion (forces, spin, and the contact forces of what already rests) the two
  // would overlap.
  States now(bodies.size());
  for (const Contact& c : touching) {
    if (isResting(restingPairs_, c.a, c.b)) continue;
    Body &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 n = c.manifold.normal;
    double fastest = 0.0;
    for (int k = 0; k < c.manifold.count; ++k)
      fastest = std::max(fastest, std::abs(n.dot(relativeVelocity(a, b, c.manifold.points[k].point))));
    if (fastest > settings::kRestingSpeed) continue;
    for (size_t i = 0; i < bodies.size(); ++i) now[i] = bodies[i].state();
    const States ahead = motion(now, dt);
    const double gap = collide(a.shape, poseOf(ahead[c.a]), b.shape, poseOf(ahead[c.b]), 0.0).separation;
    if (gap >= -touch) continue;
    // the rest of the geometric series of bounces is below kRestingSpeed: end it here
    for (int k = 0; k < c.manifold.count; ++k) {
      const Vec2 r = c.manifold.points[k].point;
      const double vn = n.dot(relativeVelocity(a, b, r));
      if (vn != 0.0) applyImpulsePair(a, b, r, (-vn / inverseEffectiveMass(a, b, r, n)) * n);
    }
    restingPairs_.emplace_back(c.a, c.b);
    // still moving: any point of either body faster than the resting speed
    const auto moves = [](const Body& body) {
      return !body.isStatic && body.v.norm() + std::abs(body.omega) * boundingRadius(body.shape) > settings::kRestingSpeed;
    };
    resting.push_back({t, c.a, c.b, moves(a) || moves(b)});
  }
}

void World::holdRestingContacts() {
  const double touch = settings::kTouchingTolerance * sceneSize_;
  std::erase_if(restingPairs_, [&](const std::pair<int, int>& p) {
    Body &a = bodies[p.first], &b = bodies[p.second];
    const Manifold m = collide(a.shape, a.pose(), b.shape, b.pose(), 100.0 * touch);
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

// contact forces of the resting pairs at state y: the smallest pushes that keep every resting
// point from accelerating into the other body (projected Gauss–Seidel on the acceleration LCP)
void World::restingForces(const States& y, std::vector<Vec2>& force, std::vector<double>& torque) const {
  struct Row {
    int a, b;
    Vec2 r, n;
    double k, lambda = 0.0;
  };
  std::vector<Row> rows;
  for (const auto& [i, j] : restingPairs_) {
    const Manifold m = collide(bodies[i].shape, poseOf(y[i]), bodies[j].shape, poseOf(y[j]),
                               100.0 * settings::kTouchingTolerance * sceneSize_);
    for (int k = 0; k < m.count; ++k) {
      Body a = bodies[i], b = bodies[j];
      a.x = y[i].x, b.x = y[j].x;
      rows.push_back({i, j, m.points[k].point, m.normal, inverseEffectiveMass(a, b, m.points[k].point, m.normal)});
    }
  }
  std::vector<Vec2> acc(y.size());
  std::vector<double> alpha(y.size());
  for (size_t i = 0; i < y.size(); ++i) {
    acc[i] = bodies[i].invMass * force[i];
    alpha[i] = bodies[i].invInertia * torque[i];
  }
  // relative normal acceleration of a row's two material points, centripetal terms included
  auto normalAcceleration = [&](const Row& w) {
    const Vec2 ra = w.r - y[w.a].x, rb = w.r - y[w.b].x;
    const Vec2 aa = acc[w.a] + cross(alpha[w.a], ra) - y[w.a].omega * y[w.a].omega * ra;
    const Vec2 ab = acc[w.b] + cross(alpha[w.b], rb) - y[w.b].omega * y[w.b].omega * rb;
    return w.n.dot(aa - ab);
  };
  for (int sweep = 0; sweep < 50; ++sweep)
    for (Row& w : rows) {
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
  for (const Row& w : rows) {
    const Vec2 f = w.lambda * w.n;
    force[w.a] += f;
    torque[w.a] += cross(w.r - y[w.a].x, f);
    force[w.b] -= f;
    torque[w.b] -= cross(w.r - y[w.b].x, f);
  }
}

}  // namespace sim::world

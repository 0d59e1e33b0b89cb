// The soft contact passes written once over a lane type (included only by soft_contacts_scalar.cpp
// and the soft_contacts_wide*.cpp): L is one lane of a block (its number type L::T, double or
// float), or half a block or a whole one at once, or two of those (soft_contacts_pair.h). Every
// operation is the same in each, in the same order, so the paths agree to the bit; and no fused
// multiply-add (the build's -ffp-contract=off).
#pragma once

#include "sim/world/soft_contacts.h"

namespace sim::world::soft {
namespace {

// a body's solver state in lanes
template <class V>
struct BodyLanes {
  V vx, vy, w, dpx, dpy, qc, qs, invMass;
};

// the normal impulses of the block's points (soft with the push when s.useBias, rigid when
// relaxing; a point with a gap is speculative: it may close the gap within the substep, no more),
// then Coulomb friction (Catto 2006), as Box2D v3's b2SolveContactTwoPoints does
template <class L>
inline void solveBlock(ContactBlockOf<typename L::T>& c, BodyStateOf<typename L::T>* bodies, const PassSettings& s, int lane) {
  using V = typename L::V;
  BodyLanes<V> A = L::gather(bodies, c.a, lane), B = L::gather(bodies, c.b, lane);
  const V nx = L::load(c.nx, lane), ny = L::load(c.ny, lane);
  const V mA = A.invMass, iA = L::load(c.invInertiaA, lane);
  const V mB = B.invMass, iB = L::load(c.invInertiaB, lane);
  const V zero = L::splat(0.0), one = L::splat(1.0);
  const auto stiff = L::touchesStatic(c.a, c.b, s.staticIndex, lane);
  const V biasRate = s.useBias ? L::select(stiff, L::splat(s.stiff.biasRate), L::splat(s.soft.biasRate)) : zero;
  const V massScale = s.useBias ? L::select(stiff, L::splat(s.stiff.massScale), L::splat(s.soft.massScale)) : one;
  const V impulseScale = s.useBias ? L::select(stiff, L::splat(s.stiff.impulseScale), L::splat(s.soft.impulseScale)) : zero;
  const V invH = L::splat(s.invH), maxPush = L::splat(-s.maxPushSpeed);
  const V dpx = A.dpx - B.dpx, dpy = A.dpy - B.dpy;
  for (auto& p : c.p) {
    const V rAx = L::load(p.rAx, lane), rAy = L::load(p.rAy, lane);
    const V rBx = L::load(p.rBx, lane), rBy = L::load(p.rBy, lane);
    // the separation now: the anchors turned by each body's rotation since the step began
    const V sAx = A.qc * rAx - A.qs * rAy, sAy = A.qs * rAx + A.qc * rAy;
    const V sBx = B.qc * rBx - B.qs * rBy, sBy = B.qs * rBx + B.qc * rBy;
    const V sep = nx * (dpx + (sAx - sBx)) + ny * (dpy + (sAy - sBy)) + L::load(p.baseSeparation, lane);
    const auto gap = L::greater(sep, zero);
    const V bias = L::select(gap, sep * invH, L::max(biasRate * sep, maxPush));
    const V pointMassScale = L::select(gap, one, massScale);
    const V pointImpulseScale = L::select(gap, zero, impulseScale);
    const V dvx = (A.vx - A.w * rAy) - (B.vx - B.w * rBy);
    const V dvy = (A.vy + A.w * rAx) - (B.vy + B.w * rBx);
    const V vn = nx * dvx + ny * dvy;
    const V old = L::load(p.normalImpulse, lane);
    const V lambda = zero - L::load(p.normalMass, lane) * pointMassScale * (vn + bias) - pointImpulseScale * old;
    const V total = L::max(old + lambda, zero);
    const V d = total - old;
    const V px = d * nx, py = d * ny;
    A.vx = A.vx + mA * px, A.vy = A.vy + mA * py, A.w = A.w + iA * (rAx * py - rAy * px);
    B.vx = B.vx - mB * px, B.vy = B.vy - mB * py, B.w = B.w - iB * (rBx * py - rBy * px);
    L::store(p.normalImpulse, lane, total);
    if (s.accumulate) L::store(p.totalNormalImpulse, lane, L::load(p.totalNormalImpulse, lane) + total);
  }
  const V tx = zero - ny, ty = nx;
  const V friction = L::load(c.friction, lane);
  for (auto& p : c.p) {
    const V rAx = L::load(p.rAx, lane), rAy = L::load(p.rAy, lane);
    const V rBx = L::load(p.rBx, lane), rBy = L::load(p.rBy, lane);
    const V dvx = (A.vx - A.w * rAy) - (B.vx - B.w * rBy);
    const V dvy = (A.vy + A.w * rAx) - (B.vy + B.w * rBx);
    const V vt = tx * dvx + ty * dvy;
    const V old = L::load(p.tangentImpulse, lane);
    const V lambda = zero - L::load(p.tangentMass, lane) * vt;
    const V limit = friction * L::load(p.normalImpulse, lane);
    const V total = L::max(zero - limit, L::min(old + lambda, limit));
    const V d = total - old;
    const V px = d * tx, py = d * ty;
    A.vx = A.vx + mA * px, A.vy = A.vy + mA * py, A.w = A.w + iA * (rAx * py - rAy * px);
    B.vx = B.vx - mB * px, B.vy = B.vy - mB * py, B.w = B.w - iB * (rBx * py - rBy * px);
    L::store(p.tangentImpulse, lane, total);
  }
  L::scatter(bodies, c.a, lane, A);
  L::scatter(bodies, c.b, lane, B);
}

// the impulses carried over (last substep's, or last step's) applied again
template <class L>
inline void warmStartBlock(ContactBlockOf<typename L::T>& c, BodyStateOf<typename L::T>* bodies, int lane) {
  using V = typename L::V;
  BodyLanes<V> A = L::gather(bodies, c.a, lane), B = L::gather(bodies, c.b, lane);
  const V nx = L::load(c.nx, lane), ny = L::load(c.ny, lane);
  const V tx = L::splat(0.0) - ny, ty = nx;
  const V mA = A.invMass, iA = L::load(c.invInertiaA, lane);
  const V mB = B.invMass, iB = L::load(c.invInertiaB, lane);
  for (auto& p : c.p) {
    const V rAx = L::load(p.rAx, lane), rAy = L::load(p.rAy, lane);
    const V rBx = L::load(p.rBx, lane), rBy = L::load(p.rBy, lane);
    const V jn = L::load(p.normalImpulse, lane), jt = L::load(p.tangentImpulse, lane);
    const V px = jn * nx + jt * tx, py = jn * ny + jt * ty;
    A.vx = A.vx + mA * px, A.vy = A.vy + mA * py, A.w = A.w + iA * (rAx * py - rAy * px);
    B.vx = B.vx - mB * px, B.vy = B.vy - mB * py, B.w = B.w - iB * (rBx * py - rBy * px);
  }
  L::scatter(bodies, c.a, lane, A);
  L::scatter(bodies, c.b, lane, B);
}

}  // namespace
}  // namespace sim::world::soft

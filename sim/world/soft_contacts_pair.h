// soft_step's contact passes on two sets of lanes at a time (included by the soft_contacts_wide*.cpp):
// two blocks of one set in AVX-512, a block's two halves in AVX2. Each operation is done on the one's
// register and then on the other's, so that their chains of dependent operations interleave: a
// block's pass is one long chain (each point's impulse waits on the velocities the one before it
// changed), and the processor cannot look far enough ahead to start the next block's while one
// waits. The blocks of a set touch disjoint bodies, so the result is the same to the bit as solving
// them one after the other. Two blocks at once took the AVX-512 step of the 5,050-box pyramid from
// 1.26 to 1.20 ms in floats and 1.82 to 1.67 in doubles, and the 210-box one's by 10 and 14 %; four
// at once ran out of registers and was slower than two; AVX2's halves gained up to 6 % (three runs
// in turn of rigidreel_stack_bench --method soft_step --precision float --precision double --recycle
// on --layout pyramid:100:packed --layout pyramid:20:packed, medians)
#pragma once

#include "sim/world/soft_contacts_kernel.h"

namespace sim::world::soft {
namespace {

// a number of each of the two blocks
template <class V>
struct PairOf {
  V lo, hi;
};
template <class V>
inline PairOf<V> operator+(const PairOf<V>& a, const PairOf<V>& b) {
  return {a.lo + b.lo, a.hi + b.hi};
}
template <class V>
inline PairOf<V> operator-(const PairOf<V>& a, const PairOf<V>& b) {
  return {a.lo - b.lo, a.hi - b.hi};
}
template <class V>
inline PairOf<V> operator*(const PairOf<V>& a, const PairOf<V>& b) {
  return {a.lo * b.lo, a.hi * b.hi};
}

// W: the lane type of one block or half block; the pair is W's lanes at a member and those kLanes
// further at the member kBytes further on (the next block's: kBytes its size, kLanes 0; or the
// same block's other half: kBytes 0, kLanes the half's width)
template <class W, unsigned long kBytes, int kLanes>
struct PairLanes {
  using T = typename W::T;
  using V = PairOf<typename W::V>;
  using Mask = PairOf<decltype(W::greater(W::splat(0.0), W::splat(0.0)))>;
  using BodyState = BodyStateOf<T>;
  template <class X>
  static X& second(X& x) {
    return *reinterpret_cast<X*>(reinterpret_cast<char*>(&x) + kBytes);
  }
  template <class X>
  static const X& second(const X& x) {
    return *reinterpret_cast<const X*>(reinterpret_cast<const char*>(&x) + kBytes);
  }
  static V load(const LanesOf<T>& x, int lane) { return {W::load(x, lane), W::load(second(x), lane + kLanes)}; }
  static void store(LanesOf<T>& x, int lane, V v) { W::store(x, lane, v.lo), W::store(second(x), lane + kLanes, v.hi); }
  static V splat(double v) { return {W::splat(v), W::splat(v)}; }
  static Mask greater(V a, V b) { return {W::greater(a.lo, b.lo), W::greater(a.hi, b.hi)}; }
  static Mask touchesStatic(const int* a, const int* b, int dummy, int lane) {
    return {W::touchesStatic(a, b, dummy, lane), W::touchesStatic(&second(*a), &second(*b), dummy, lane + kLanes)};
  }
  static V select(Mask m, V a, V b) { return {W::select(m.lo, a.lo, b.lo), W::select(m.hi, a.hi, b.hi)}; }
  static V max(V a, V b) { return {W::max(a.lo, b.lo), W::max(a.hi, b.hi)}; }
  static V min(V a, V b) { return {W::min(a.lo, b.lo), W::min(a.hi, b.hi)}; }
  static BodyLanes<V> gather(const BodyState* bodies, const int* index, int lane) {
    const auto a = W::gather(bodies, index, lane), b = W::gather(bodies, &second(*index), lane + kLanes);
    return {{a.vx, b.vx},   {a.vy, b.vy}, {a.w, b.w},   {a.dpx, b.dpx},
            {a.dpy, b.dpy}, {a.qc, b.qc}, {a.qs, b.qs}, {a.invMass, b.invMass}};
  }
  static void scatter(BodyState* bodies, const int* index, int lane, const BodyLanes<V>& v) {
    W::scatter(bodies, index, lane, {v.vx.lo, v.vy.lo, v.w.lo, v.dpx.lo, v.dpy.lo, v.qc.lo, v.qs.lo, v.invMass.lo});
    W::scatter(bodies, &second(*index), lane + kLanes,
               {v.vx.hi, v.vy.hi, v.w.hi, v.dpx.hi, v.dpy.hi, v.qc.hi, v.qs.hi, v.invMass.hi});
  }
};

// W's whole blocks two at a time: a block and the one after it
template <class W>
using TwoBlocks = PairLanes<W, sizeof(ContactBlockOf<typename W::T>), 0>;
// W's half blocks two at a time: a block's two halves of kHalf lanes
template <class W, int kHalf>
using TwoHalves = PairLanes<W, 0, kHalf>;

}  // namespace
}  // namespace sim::world::soft

// soft_step's contact passes in floats (sim: {precision: float}) eight lanes at once, each block of
// sixteen as two halves in one AVX2 register of eight floats each (GCC's vector extensions;
// compiled with -mavx2 where the compiler targets x86-64, sim/CMakeLists.txt; elsewhere the same
// code in the target's own vectors). The bodies' records (eight floats, one register each) are read
// whole and transposed into fields, and written back the same way. The result is the scalar path's
// to the bit (same operations, same order, no fused multiply-add).
#include "sim/world/soft_contacts_kernel.h"
#include "sim/world/soft_contacts_pair.h"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace sim::world::soft {
namespace {

static_assert(kLanesOf<float> == 16, "a block is two halves of eight lanes");

typedef float F8 __attribute__((vector_size(32)));
typedef int I8 __attribute__((vector_size(32)));

struct WideFloatLanes {
  using T = float;
  using V = F8;
  using BodyState = BodyStateOf<float>;
  // `half`: the block's first eight lanes (0) or its last eight (8)
  static V load(const LanesOf<T>& x, int half) { return *reinterpret_cast<const F8*>(x.l + half); }
  static void store(LanesOf<T>& x, int half, V v) { *reinterpret_cast<F8*>(x.l + half) = v; }
  static V splat(double d) {
    const float v = static_cast<float>(d);
    return F8{v, v, v, v, v, v, v, v};
  }
  static I8 greater(V a, V b) { return a > b; }
  static I8 touchesStatic(const int* a, const int* b, int dummy, int half) {
    I8 ia, ib;
    __builtin_memcpy(&ia, a + half, sizeof ia);
    __builtin_memcpy(&ib, b + half, sizeof ib);
    return (ia == dummy) | (ib == dummy);
  }
#if defined(__AVX2__)
  // a where m, else b (m is all ones or all zeros in each lane, as the scalar path's m ? a : b)
  static V select(I8 m, V a, V b) { return F8(_mm256_blendv_ps(__m256(b), __m256(a), __m256(m))); }
  // vmaxps(x, y) is x > y ? x : y, vminps(x, y) x < y ? x : y: the scalar path's a < b ? b : a and
  // b < a ? b : a with the operands so, NaN and signed zeros included
  static V max(V a, V b) { return F8(_mm256_max_ps(__m256(b), __m256(a))); }
  static V min(V a, V b) { return F8(_mm256_min_ps(__m256(b), __m256(a))); }
  // the eight lanes' records read as rows and turned into columns: an 8 x 8 transpose in three
  // rounds of shuffles (pairs of rows, quads within each 128-bit half, then the halves)
  static BodyLanes<V> gather(const BodyState* bodies, const int* all, int half) {
    const int* index = all + half;
    __m256 r[8];
    for (int k = 0; k < 8; ++k) r[k] = _mm256_load_ps(&bodies[index[k]].vx);
    __m256 t[8];
    for (int k = 0; k < 4; ++k) {
      t[2 * k] = _mm256_unpacklo_ps(r[2 * k], r[2 * k + 1]);
      t[2 * k + 1] = _mm256_unpackhi_ps(r[2 * k], r[2 * k + 1]);
    }
    // rows 0-3 (h = 0) and 4-7 (h = 1): fields (0 | 4), (1 | 5), (2 | 6), (3 | 7) in each half
    constexpr int kLow = _MM_SHUFFLE(1, 0, 1, 0), kHigh = _MM_SHUFFLE(3, 2, 3, 2);
    __m256 u[8];
    for (int h = 0; h < 2; ++h) {
      u[4 * h + 0] = _mm256_shuffle_ps(t[4 * h + 0], t[4 * h + 2], kLow);
      u[4 * h + 1] = _mm256_shuffle_ps(t[4 * h + 0], t[4 * h + 2], kHigh);
      u[4 * h + 2] = _mm256_shuffle_ps(t[4 * h + 1], t[4 * h + 3], kLow);
    }
    u[3] = _mm256_shuffle_ps(t[1], t[3], kHigh);
    u[7] = _mm256_shuffle_ps(t[5], t[7], kHigh);
    // all eight rows of a field: the low halves hold fields 0-3, the high ones 4-7
    const auto low = [&](int q) { return F8(_mm256_permute2f128_ps(u[q], u[q + 4], 0x20)); };
    const auto high = [&](int q) { return F8(_mm256_permute2f128_ps(u[q], u[q + 4], 0x31)); };
    return {low(0), low(1), low(2), high(0), high(1), high(2), high(3), low(3)};
  }
  // the velocities (and the inverse mass, as it was) written back as the first half of each record, lane 0 first (the lanes touch
  // distinct bodies, or the static record whose velocity stays zero)
  static void scatter(BodyState* bodies, const int* all, int half, const BodyLanes<V>& b) {
    const int* index = all + half;
    const __m256 vLow = _mm256_unpacklo_ps(__m256(b.vx), __m256(b.vy)), vHigh = _mm256_unpackhi_ps(__m256(b.vx), __m256(b.vy));
    const __m256 wLow = _mm256_unpacklo_ps(__m256(b.w), __m256(b.invMass)),
                 wHigh = _mm256_unpackhi_ps(__m256(b.w), __m256(b.invMass));
    constexpr int kLow = _MM_SHUFFLE(1, 0, 1, 0), kHigh = _MM_SHUFFLE(3, 2, 3, 2);
    // (vx, vy, w, 1/m) of lanes k (low half) and k + 4 (high half), for k = 0, 1, 2, 3
    const __m256 rows[4] = {_mm256_shuffle_ps(vLow, wLow, kLow), _mm256_shuffle_ps(vLow, wLow, kHigh),
                            _mm256_shuffle_ps(vHigh, wHigh, kLow), _mm256_shuffle_ps(vHigh, wHigh, kHigh)};
    for (int k = 0; k < 4; ++k) {
      _mm_store_ps(&bodies[index[k]].vx, _mm256_castps256_ps128(rows[k]));
      _mm_store_ps(&bodies[index[k + 4]].vx, _mm256_extractf128_ps(rows[k], 1));
    }
  }
#else
  static V select(I8 m, V a, V b) { return reinterpret_cast<F8>((reinterpret_cast<I8>(a) & m) | (reinterpret_cast<I8>(b) & ~m)); }
  static V max(V a, V b) { return select(a < b, b, a); }
  static V min(V a, V b) { return select(b < a, b, a); }
  static BodyLanes<V> gather(const BodyState* bodies, const int* all, int half) {
    BodyLanes<V> b;
    for (int k = 0; k < 8; ++k) {
      const BodyState& s = bodies[all[half + k]];
      b.vx[k] = s.vx, b.vy[k] = s.vy, b.w[k] = s.w, b.dpx[k] = s.dpx, b.dpy[k] = s.dpy, b.qc[k] = s.qc, b.qs[k] = s.qs,
      b.invMass[k] = s.invMass;
    }
    return b;
  }
  static void scatter(BodyState* bodies, const int* all, int half, const BodyLanes<V>& v) {
    for (int k = 0; k < 8; ++k) {
      BodyState& b = bodies[all[half + k]];
      b.vx = v.vx[k], b.vy = v.vy[k], b.w = v.w[k];
    }
  }
#endif
};

}  // namespace

void warmStartWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  for (int i = begin; i < end; ++i) warmStartBlock<TwoHalves<WideFloatLanes, 8>>(blocks[i], bodies, 0);
}

void solveWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i) solveBlock<TwoHalves<WideFloatLanes, 8>>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

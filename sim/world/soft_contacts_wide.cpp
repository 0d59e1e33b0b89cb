// soft_step's contact passes in doubles four lanes at once, each block of eight as two halves, in GCC's vector extensions:
// compiled with -mavx2 where the compiler targets x86-64 (sim/CMakeLists.txt), one AVX2 instruction per operation on four
// doubles; elsewhere the same code in the target's own vectors. The result is the scalar path's to the bit (same operations,
// same order, no fused multiply-add). Floats: soft_contacts_wide_float.cpp.
#include "sim/core/avx2_transpose.h"
#include "sim/world/soft_contacts_kernel.h"
#include "sim/world/soft_contacts_pair.h"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace sim::world::soft {
namespace {

static_assert(kLanesOf<double> == 8, "a block is two halves of four lanes");

typedef double V4 __attribute__((vector_size(32)));
typedef long long M4 __attribute__((vector_size(32)));

struct WideLanes {
  using T = double;
  using V = V4;
  using BodyState = BodyStateOf<double>;
  // `half`: the block's first four lanes (0) or its last four (4)
  static V load(const LanesOf<T>& x, int half) { return *reinterpret_cast<const V4*>(x.l + half); }
  static void store(LanesOf<T>& x, int half, V v) { *reinterpret_cast<V4*>(x.l + half) = v; }
  static V splat(double v) { return V4{v, v, v, v}; }
  static M4 greater(V a, V b) { return a > b; }
  static M4 touchesStatic(const int* a, const int* b, int dummy, int half) {
    typedef int I4 __attribute__((vector_size(16)));
    I4 ia, ib;
    __builtin_memcpy(&ia, a + half, sizeof ia);
    __builtin_memcpy(&ib, b + half, sizeof ib);
    return __builtin_convertvector((ia == dummy) | (ib == dummy), M4);
  }
#if defined(__AVX2__)
  // a where m, else b (m is all ones or all zeros in each lane, as the scalar path's m ? a : b)
  static V select(M4 m, V a, V b) { return V4(_mm256_blendv_pd(__m256d(b), __m256d(a), __m256d(m))); }
  // vmaxpd(x, y) is x > y ? x : y, vminpd(x, y) x < y ? x : y: the scalar path's a < b ? b : a and
  // b < a ? b : a with the operands so, NaN and signed zeros included
  static V max(V a, V b) { return V4(_mm256_max_pd(__m256d(b), __m256d(a))); }
  static V min(V a, V b) { return V4(_mm256_min_pd(__m256d(b), __m256d(a))); }
  // four records' first (or second) halves, read as rows and turned into columns
  static void transpose(__m256d& r0, __m256d& r1, __m256d& r2, __m256d& r3) { sim::core::transpose4(r0, r1, r2, r3); }
  static BodyLanes<V> gather(const BodyState* bodies, const int* all, int half) {
    const int* index = all + half;
    const double* b0 = &bodies[index[0]].vx;
    const double* b1 = &bodies[index[1]].vx;
    const double* b2 = &bodies[index[2]].vx;
    const double* b3 = &bodies[index[3]].vx;
    __m256d v0 = _mm256_load_pd(b0), v1 = _mm256_load_pd(b1), v2 = _mm256_load_pd(b2), v3 = _mm256_load_pd(b3);
    __m256d p0 = _mm256_load_pd(b0 + 4), p1 = _mm256_load_pd(b1 + 4), p2 = _mm256_load_pd(b2 + 4), p3 = _mm256_load_pd(b3 + 4);
    transpose(v0, v1, v2, v3);
    transpose(p0, p1, p2, p3);
    return {V4(v0), V4(v1), V4(v2), V4(p0), V4(p1), V4(p2), V4(p3), V4(v3)};
  }
  static void scatter(BodyState* bodies, const int* all, int half, const BodyLanes<V>& b) {
    const int* index = all + half;
    __m256d r0 = __m256d(b.vx), r1 = __m256d(b.vy), r2 = __m256d(b.w), r3 = __m256d(b.invMass);
    transpose(r0, r1, r2, r3);
    _mm256_store_pd(&bodies[index[0]].vx, r0);
    _mm256_store_pd(&bodies[index[1]].vx, r1);
    _mm256_store_pd(&bodies[index[2]].vx, r2);
    _mm256_store_pd(&bodies[index[3]].vx, r3);
  }
#else
  static V select(M4 m, V a, V b) { return reinterpret_cast<V4>((reinterpret_cast<M4>(a) & m) | (reinterpret_cast<M4>(b) & ~m)); }
  static V max(V a, V b) { return select(a < b, b, a); }
  static V min(V a, V b) { return select(b < a, b, a); }
  static BodyLanes<V> gather(const BodyState* bodies, const int* all, int half) {
    const int* index = all + half;
    const BodyState &b0 = bodies[index[0]], &b1 = bodies[index[1]], &b2 = bodies[index[2]], &b3 = bodies[index[3]];
    return {V4{b0.vx, b1.vx, b2.vx, b3.vx},     V4{b0.vy, b1.vy, b2.vy, b3.vy},
            V4{b0.w, b1.w, b2.w, b3.w},         V4{b0.dpx, b1.dpx, b2.dpx, b3.dpx},
            V4{b0.dpy, b1.dpy, b2.dpy, b3.dpy}, V4{b0.qc, b1.qc, b2.qc, b3.qc},
            V4{b0.qs, b1.qs, b2.qs, b3.qs},     V4{b0.invMass, b1.invMass, b2.invMass, b3.invMass}};
  }
  static void scatter(BodyState* bodies, const int* all, int half, const BodyLanes<V>& v) {
    const int* index = all + half;
    for (int k = 0; k < 4; ++k) {
      BodyState& b = bodies[index[k]];
      b.vx = v.vx[k], b.vy = v.vy[k], b.w = v.w[k];
    }
  }
#endif
};

}  // namespace

void warmStartWide(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies) {
  for (int i = begin; i < end; ++i) warmStartBlock<TwoHalves<WideLanes, 4>>(blocks[i], bodies, 0);
}

void solveWide(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i) solveBlock<TwoHalves<WideLanes, 4>>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

// soft_step's contact passes eight lanes at once, a whole block in one AVX-512 register of eight
// doubles (GCC's vector extensions; compiled with -mavx512f where the compiler targets x86-64,
// sim/CMakeLists.txt, and chosen at run time). The bodies' records are read whole and transposed into
// fields, and written back the same way; a block's lanes touch distinct bodies (or the static
// record, whose velocity stays zero), so the order of the writes within a block changes nothing. The result is the scalar path's
// to the bit (same operations, same order, no fused multiply-add).
#include "sim/world/soft_contacts_kernel.h"
#include "sim/world/soft_contacts_pair.h"

#if defined(__AVX512F__)
#include <immintrin.h>

#include <cstddef>

namespace sim::world::soft {
namespace {

static_assert(kLanesOf<double> == 8, "a block is one register of eight lanes");

typedef double V8 __attribute__((vector_size(64)));

struct Wide512Lanes {
  using T = double;
  using V = V8;
  using BodyState = BodyStateOf<double>;
  static V load(const LanesOf<T>& x, int) { return *reinterpret_cast<const V8*>(x.l); }
  static void store(LanesOf<T>& x, int, V v) { *reinterpret_cast<V8*>(x.l) = v; }
  static V splat(double v) { return V8{v, v, v, v, v, v, v, v}; }
  // a comparison into a mask register, and a blend by it (a NaN compares false, as the scalar
  // path's a > b): with max and min below, one instruction each where the vector extensions' and,
  // andnot and or took three; the 5,050-box pyramid's double step with recycling went from 1.95
  // to 1.76 ms (two runs in turn, with the float blocks' change; rigidreel_stack_bench)
  static __mmask8 greater(V a, V b) { return _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_GT_OQ); }
  // the lanes whose A or B is the static record: a block's a and b side by side are one register
  static_assert(offsetof(ContactBlockOf<double>, b) == offsetof(ContactBlockOf<double>, a) + 8 * sizeof(int));
  static __mmask8 touchesStatic(const int* a, const int*, int dummy, int) {
    const __mmask16 m = _mm512_cmpeq_epi32_mask(_mm512_load_si512(a), _mm512_set1_epi32(dummy));
    return __mmask8((m | (m >> 8)) & 0xff);
  }
  static V select(__mmask8 m, V a, V b) { return V8(_mm512_mask_blend_pd(m, __m512d(b), __m512d(a))); }
  // vmaxpd(x, y) is x > y ? x : y, vminpd(x, y) x < y ? x : y: the scalar path's a < b ? b : a and
  // b < a ? b : a with the operands so, NaN and signed zeros included
  static V max(V a, V b) { return V8(_mm512_maskz_max_pd(0xff, __m512d(b), __m512d(a))); }
  static V min(V a, V b) { return V8(_mm512_maskz_min_pd(0xff, __m512d(b), __m512d(a))); }
  // AVX-512's shuffles in their masked forms with every lane kept (GCC 12's unmasked ones warn of
  // their undefined source)
  static __m512d unpackLow(__m512d a, __m512d b) { return _mm512_maskz_unpacklo_pd(0xff, a, b); }
  static __m512d unpackHigh(__m512d a, __m512d b) { return _mm512_maskz_unpackhi_pd(0xff, a, b); }
  template <int kPick>
  static __m512d shuffle2(__m512d a, __m512d b) {
    return _mm512_maskz_shuffle_f64x2(0xff, a, b, kPick);
  }
  static __m256d lowerHalf(__m512d a) { return __builtin_shufflevector(a, a, 0, 1, 2, 3); }
  static __m256d upperHalf(__m512d a) { return __builtin_shufflevector(a, a, 4, 5, 6, 7); }
  // the eight lanes' records read whole (a record is one register) and turned into columns: an
  // 8 x 8 transpose in three rounds of shuffles (Intel's optimization manual, 512-bit transposes).
  // On AMD's Zen 4 this took the 5,050-box pyramid's step from 4.75 to 4.2 ms against AVX-512's
  // gather of each field (rigidreel_stack_bench --layout pyramid:100:packed --method soft_step)
  static BodyLanes<V> gather(const BodyState* bodies, const int* index, int) {
    __m512d r[8];
    for (int k = 0; k < 8; ++k) r[k] = _mm512_load_pd(&bodies[index[k]].vx);
    // pairs of rows: even fields, odd fields
    __m512d t[8];
    for (int k = 0; k < 4; ++k) {
      t[2 * k] = unpackLow(r[2 * k], r[2 * k + 1]);
      t[2 * k + 1] = unpackHigh(r[2 * k], r[2 * k + 1]);
    }
    // quads of rows: fields (0, 4), (2, 6), (1, 5), (3, 7) of rows 0-3, then of rows 4-7
    constexpr int kEven = _MM_SHUFFLE(2, 0, 2, 0), kOdd = _MM_SHUFFLE(3, 1, 3, 1);
    __m512d u[8];
    for (int h = 0; h < 2; ++h) {
      u[4 * h + 0] = shuffle2<kEven>(t[4 * h + 0], t[4 * h + 2]);
      u[4 * h + 1] = shuffle2<kOdd>(t[4 * h + 0], t[4 * h + 2]);
      u[4 * h + 2] = shuffle2<kEven>(t[4 * h + 1], t[4 * h + 3]);
      u[4 * h + 3] = shuffle2<kOdd>(t[4 * h + 1], t[4 * h + 3]);
    }
    // all eight rows of a field
    const auto even = [&](int q) { return V8(shuffle2<kEven>(u[q], u[q + 4])); };
    const auto odd = [&](int q) { return V8(shuffle2<kOdd>(u[q], u[q + 4])); };
    return {even(0), even(2), even(1), odd(0), odd(2), odd(1), odd(3), even(3)};
  }
  // the velocities (and the inverse mass, as it was) written back as the first half of each record, lane 0 first (the lanes touch
  // distinct bodies, or the static record whose velocity stays zero)
  static void scatter(BodyState* bodies, const int* index, int, const BodyLanes<V>& b) {
    const __m512d vEven = unpackLow(__m512d(b.vx), __m512d(b.vy)), vOdd = unpackHigh(__m512d(b.vx), __m512d(b.vy));
    const __m512d wEven = unpackLow(__m512d(b.w), __m512d(b.invMass)), wOdd = unpackHigh(__m512d(b.w), __m512d(b.invMass));
    // (vx, vy, w, 1/m) of lanes 0 and 2 (or 4 and 6, or the odd ones) in one register
    const __m512i low = _mm512_set_epi64(11, 10, 3, 2, 9, 8, 1, 0), high = _mm512_set_epi64(15, 14, 7, 6, 13, 12, 5, 4);
    const __m512d rows[4] = {_mm512_permutex2var_pd(vEven, low, wEven), _mm512_permutex2var_pd(vOdd, low, wOdd),
                             _mm512_permutex2var_pd(vEven, high, wEven), _mm512_permutex2var_pd(vOdd, high, wOdd)};
    // rows[q] holds lanes (2q, 2q + 2) for q = 0, 1 as (0, 2), (1, 3); q = 2, 3 as (4, 6), (5, 7)
    constexpr int kFirst[4] = {0, 1, 4, 5};
    for (int q = 0; q < 4; ++q) {
      _mm256_store_pd(&bodies[index[kFirst[q]]].vx, lowerHalf(rows[q]));
      _mm256_store_pd(&bodies[index[kFirst[q] + 2]].vx, upperHalf(rows[q]));
    }
  }
};

}  // namespace

void warmStartWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies) {
  int i = begin;
  for (; i + 1 < end; i += 2) warmStartBlock<TwoBlocks<Wide512Lanes>>(blocks[i], bodies, 0);
  if (i < end) warmStartBlock<Wide512Lanes>(blocks[i], bodies, 0);
}

void solveWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s) {
  int i = begin;
  for (; i + 1 < end; i += 2) solveBlock<TwoBlocks<Wide512Lanes>>(blocks[i], bodies, s, 0);
  if (i < end) solveBlock<Wide512Lanes>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

#else
// without AVX-512 in the build, the scalar passes (never chosen: avx512Available() says no)
namespace sim::world::soft {
void warmStartWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies) {
  warmStartScalar(blocks, begin, end, bodies);
}
void solveWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s) {
  solveScalar(blocks, begin, end, bodies, s);
}
}  // namespace sim::world::soft
#endif

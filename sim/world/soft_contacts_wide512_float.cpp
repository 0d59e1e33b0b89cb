// soft_step's contact passes in floats (sim: {precision: float}) sixteen lanes at once, a whole
// block in one AVX-512 register of sixteen floats (GCC's vector extensions; compiled with -mavx512f
// where the compiler targets x86-64, sim/CMakeLists.txt, and chosen at run time). Against eight
// lanes at a time (AVX2's halves, or AVX-512VL's registers, as floats were solved before) each
// block's pass takes half the instructions. On this AMD EPYC (Zen 5, AVX-512 at full width) that
// took the 5,050-box pyramid's float step with recycling from 1.72 to 1.27 ms, two runs in turn
// (rigidreel_stack_bench --layout pyramid:100:packed --method soft_step --precision float
// --recycle on; Box2D v3's 1.66-1.68 ms in the same runs). The result is the scalar path's to the
// bit (same operations, same order, no fused multiply-add).
#include "sim/world/soft_contacts_kernel.h"
#include "sim/world/soft_contacts_pair.h"

#if defined(__AVX512F__)
#include <immintrin.h>

namespace sim::world::soft {
namespace {

static_assert(kLanesOf<float> == 16, "a block is one register of sixteen lanes");

typedef float F16 __attribute__((vector_size(64)));
typedef float F8 __attribute__((vector_size(32)));

struct Wide512FloatLanes {
  using T = float;
  using V = F16;
  using BodyState = BodyStateOf<float>;
  static V load(const LanesOf<T>& x, int) { return *reinterpret_cast<const F16*>(x.l); }
  static void store(LanesOf<T>& x, int, V v) { *reinterpret_cast<F16*>(x.l) = v; }
  static V splat(double d) {
    const float v = static_cast<float>(d);
    return F16{v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v};
  }
  // a comparison into a mask register, and a blend by it (a NaN compares false, as the scalar
  // path's a > b)
  static __mmask16 greater(V a, V b) { return _mm512_cmp_ps_mask(__m512(a), __m512(b), _CMP_GT_OQ); }
  static __mmask16 touchesStatic(const int* a, const int* b, int dummy, int) {
    const __m512i d = _mm512_set1_epi32(dummy);
    return _mm512_cmpeq_epi32_mask(_mm512_load_si512(a), d) | _mm512_cmpeq_epi32_mask(_mm512_load_si512(b), d);
  }
  static V select(__mmask16 m, V a, V b) { return F16(_mm512_mask_blend_ps(m, __m512(b), __m512(a))); }
  // vmaxps(x, y) is x > y ? x : y, vminps(x, y) x < y ? x : y: the scalar path's a < b ? b : a and
  // b < a ? b : a with the operands so, NaN and signed zeros included
  static V max(V a, V b) { return F16(_mm512_maskz_max_ps(0xffff, __m512(b), __m512(a))); }
  static V min(V a, V b) { return F16(_mm512_maskz_min_ps(0xffff, __m512(b), __m512(a))); }
  // every lane kept: AVX-512's shuffles in their masked forms (GCC 12's unmasked ones warn of their
  // undefined source)
  static constexpr __mmask16 kAll = 0xffff;
  // two records (eight floats each) side by side in one register
  static __m512 twoRecords(const BodyState& low, const BodyState& high) {
    const F8 a = *reinterpret_cast<const F8*>(&low.vx), b = *reinterpret_cast<const F8*>(&high.vx);
    return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  }
  template <int kFirst>
  static __m128 quarter(__m512 a) {
    return __builtin_shufflevector(a, a, kFirst, kFirst + 1, kFirst + 2, kFirst + 3);
  }
  // the sixteen lanes' records turned into columns: AVX2's 8 x 8 transpose (soft_contacts_wide_float.cpp)
  // in each 256-bit half at once, the rows paired so that one shuffle of 128-bit quarters puts
  // every field's sixteen rows in order
  static BodyLanes<V> gather(const BodyState* bodies, const int* index, int) {
    // row k holds records (k, k + 4) for k < 4 and (k + 4, k + 8) after
    __m512 r[8];
    for (int k = 0; k < 8; ++k) {
      const int first = k < 4 ? k : k + 4;
      r[k] = twoRecords(bodies[index[first]], bodies[index[first + 4]]);
    }
    __m512 t[8];
    for (int k = 0; k < 4; ++k) {
      t[2 * k] = _mm512_maskz_unpacklo_ps(kAll, r[2 * k], r[2 * k + 1]);
      t[2 * k + 1] = _mm512_maskz_unpackhi_ps(kAll, r[2 * k], r[2 * k + 1]);
    }
    constexpr int kLow = _MM_SHUFFLE(1, 0, 1, 0), kHigh = _MM_SHUFFLE(3, 2, 3, 2);
    __m512 u[8];
    for (int h = 0; h < 2; ++h) {
      u[4 * h + 0] = _mm512_maskz_shuffle_ps(kAll, t[4 * h + 0], t[4 * h + 2], kLow);
      u[4 * h + 1] = _mm512_maskz_shuffle_ps(kAll, t[4 * h + 0], t[4 * h + 2], kHigh);
      u[4 * h + 2] = _mm512_maskz_shuffle_ps(kAll, t[4 * h + 1], t[4 * h + 3], kLow);
    }
    u[3] = _mm512_maskz_shuffle_ps(kAll, t[1], t[3], kHigh);
    u[7] = _mm512_maskz_shuffle_ps(kAll, t[5], t[7], kHigh);
    // u[q]'s quarters: field q of records 0-3, field q + 4 of 0-3, field q of 4-7, field q + 4 of
    // 4-7; u[q + 4]'s the same of records 8-15
    const auto low = [&](int q) { return F16(_mm512_maskz_shuffle_f32x4(kAll, u[q], u[q + 4], _MM_SHUFFLE(2, 0, 2, 0))); };
    const auto high = [&](int q) { return F16(_mm512_maskz_shuffle_f32x4(kAll, u[q], u[q + 4], _MM_SHUFFLE(3, 1, 3, 1))); };
    return {low(0), low(1), low(2), high(0), high(1), high(2), high(3), low(3)};
  }
  // the velocities (and the inverse mass, as it was) written back as the first quarter of each record (the lanes touch distinct
  // bodies, or the static record whose velocity stays zero)
  static void scatter(BodyState* bodies, const int* index, int, const BodyLanes<V>& b) {
    const __m512 vLow = _mm512_maskz_unpacklo_ps(kAll, __m512(b.vx), __m512(b.vy));
    const __m512 vHigh = _mm512_maskz_unpackhi_ps(kAll, __m512(b.vx), __m512(b.vy));
    const __m512 wLow = _mm512_maskz_unpacklo_ps(kAll, __m512(b.w), __m512(b.invMass));
    const __m512 wHigh = _mm512_maskz_unpackhi_ps(kAll, __m512(b.w), __m512(b.invMass));
    constexpr int kLow = _MM_SHUFFLE(1, 0, 1, 0), kHigh = _MM_SHUFFLE(3, 2, 3, 2);
    // rows[k]'s quarter j: (vx, vy, w, 1/m) of lane 4j + k
    const __m512 rows[4] = {_mm512_maskz_shuffle_ps(kAll, vLow, wLow, kLow), _mm512_maskz_shuffle_ps(kAll, vLow, wLow, kHigh),
                            _mm512_maskz_shuffle_ps(kAll, vHigh, wHigh, kLow),
                            _mm512_maskz_shuffle_ps(kAll, vHigh, wHigh, kHigh)};
    for (int k = 0; k < 4; ++k) {
      _mm_store_ps(&bodies[index[k]].vx, quarter<0>(rows[k]));
      _mm_store_ps(&bodies[index[4 + k]].vx, quarter<4>(rows[k]));
      _mm_store_ps(&bodies[index[8 + k]].vx, quarter<8>(rows[k]));
      _mm_store_ps(&bodies[index[12 + k]].vx, quarter<12>(rows[k]));
    }
  }
};

}  // namespace

void warmStartWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  int i = begin;
  for (; i + 1 < end; i += 2) warmStartBlock<TwoBlocks<Wide512FloatLanes>>(blocks[i], bodies, 0);
  if (i < end) warmStartBlock<Wide512FloatLanes>(blocks[i], bodies, 0);
}

void solveWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  int i = begin;
  for (; i + 1 < end; i += 2) solveBlock<TwoBlocks<Wide512FloatLanes>>(blocks[i], bodies, s, 0);
  if (i < end) solveBlock<Wide512FloatLanes>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

#else
// without AVX-512 in the build, AVX2's halves (never chosen: avx512Available() says no)
namespace sim::world::soft {
void warmStartWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  warmStartWide(blocks, begin, end, bodies);
}
void solveWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  solveWide(blocks, begin, end, bodies, s);
}
}  // namespace sim::world::soft
#endif

// soft_step's contact passes eight lanes at once, a whole block in one AVX-512 register of eight
// doubles (GCC's vector extensions; compiled with -mavx512f where the compiler targets x86-64,
// sim/CMakeLists.txt, and chosen at run time). The bodies are read and written by AVX-512's
// gather and scatter of one field of eight records; a block's lanes touch distinct bodies (or the
// static record, whose velocity stays zero), so the scatter's order within a block changes
// nothing. The result is the scalar path's to the bit (same operations, same order, no fused
// multiply-add).
#include "sim/world/soft_contacts_kernel.h"

#if defined(__AVX512F__)
#include <immintrin.h>

namespace sim::world::soft {
namespace {

static_assert(kLanes == 8, "a block is one register of eight lanes");

typedef double V8 __attribute__((vector_size(64)));
typedef long long M8 __attribute__((vector_size(64)));

struct Wide512Lanes {
  using V = V8;
  static V load(const Lanes& x, int) { return *reinterpret_cast<const V8*>(x.l); }
  static void store(Lanes& x, int, V v) { *reinterpret_cast<V8*>(x.l) = v; }
  static V splat(double v) { return V8{v, v, v, v, v, v, v, v}; }
  static M8 greater(V a, V b) { return a > b; }
  // a where m, else b, bit by bit (as the scalar path's m ? a : b)
  static V select(M8 m, V a, V b) { return reinterpret_cast<V8>((reinterpret_cast<M8>(a) & m) | (reinterpret_cast<M8>(b) & ~m)); }
  static V max(V a, V b) { return select(a < b, b, a); }
  static V min(V a, V b) { return select(b < a, b, a); }
  // each lane's record, as an index in doubles from the first record's vx, plus a field's offset
  static __m256i offsets(const int* index) {
    return _mm256_slli_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(index)), 3);
  }
  static V field(const double* base, __m256i at, int k) {
    // (the masked form with a zero source: GCC 12's unmasked one warns of its undefined source)
    return V8(_mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xff, _mm256_add_epi32(at, _mm256_set1_epi32(k)), base, 8));
  }
  static BodyLanes<V> gather(const BodyState* bodies, const int* index, int) {
    const double* base = &bodies[0].vx;
    const __m256i at = offsets(index);
    return {field(base, at, 0), field(base, at, 1), field(base, at, 2), field(base, at, 4),
            field(base, at, 5), field(base, at, 6), field(base, at, 7)};
  }
  static void scatter(BodyState* bodies, const int* index, int, const BodyLanes<V>& b) {
    double* base = &bodies[0].vx;
    const __m256i at = offsets(index);
    _mm512_i32scatter_pd(base, at, __m512d(b.vx), 8);
    _mm512_i32scatter_pd(base, _mm256_add_epi32(at, _mm256_set1_epi32(1)), __m512d(b.vy), 8);
    _mm512_i32scatter_pd(base, _mm256_add_epi32(at, _mm256_set1_epi32(2)), __m512d(b.w), 8);
  }
};

}  // namespace

void warmStartWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies) {
  for (int i = begin; i < end; ++i) warmStartBlock<Wide512Lanes>(blocks[i], bodies, 0);
}

void solveWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i) solveBlock<Wide512Lanes>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

#else
// without AVX-512 in the build, the scalar passes (never chosen: wide512Available() says no)
namespace sim::world::soft {
void warmStartWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies) { warmStartScalar(blocks, begin, end, bodies); }
void solveWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s) {
  solveScalar(blocks, begin, end, bodies, s);
}
}  // namespace sim::world::soft
#endif

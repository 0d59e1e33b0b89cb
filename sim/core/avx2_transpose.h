// Four rows of four doubles turned into four columns in AVX2 (a row per SIMD lane in, a number per
// register out): for the units compiled with -mavx2 alone (soft_contacts_wide.cpp,
// quad_lanes_wide.cpp), which share it with no other.
#pragma once

#if defined(__AVX2__)
#include <immintrin.h>

namespace sim::core {

inline void transpose4(__m256d& r0, __m256d& r1, __m256d& r2, __m256d& r3) {
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  r0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  r1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  r2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  r3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}

}  // namespace sim::core
#endif

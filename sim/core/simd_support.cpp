#include "sim/core/simd_support.h"

namespace sim::core {

bool avx2Available() {
#if defined(RIGIDREEL_WIDE_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return true;
#endif
}

bool avx512Available() {
#if defined(RIGIDREEL_WIDE_AVX512)
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  return avx512;
#else
  return false;
#endif
}

}  // namespace sim::core

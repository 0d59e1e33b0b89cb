// Which SIMD units this processor runs: the wide units (compiled with -mavx2, -mavx512f where the
// compiler targets x86-64: sim/CMakeLists.txt) are chosen at run time by these, asked once, outside
// those units so that nothing of them runs on a processor without the instructions. Elsewhere the
// wide units are the target's own vectors, and avx2Available() says yes, avx512Available() no.
#pragma once

namespace sim::core {

bool avx2Available();
// AVX-512's foundation (AVX512F), all the wide512 units use
bool avx512Available();

}  // namespace sim::core

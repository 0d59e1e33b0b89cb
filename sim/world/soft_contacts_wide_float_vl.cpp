// soft_step's float passes (soft_contacts_float_lanes.h) compiled with -mavx512f -mavx512vl where
// the compiler targets x86-64 (sim/CMakeLists.txt), chosen at run time where the processor has
// them: the AVX2 unit's instructions with AVX-512's 32 registers, which hold what the AVX2 build
// spills (a pass's solve of a block in 476 instructions instead of 530).
#include "sim/world/soft_contacts_float_lanes.h"

namespace sim::world::soft {

#if defined(__AVX512VL__)
void warmStartWideVl(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  for (int i = begin; i < end; ++i) warmStartBlock<WideFloatLanes>(blocks[i], bodies, 0);
}

void solveWideVl(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i) solveBlock<WideFloatLanes>(blocks[i], bodies, s, 0);
}
#else
// without AVX-512 in the build, the AVX2 passes (never chosen: avx512Available() says no)
void warmStartWideVl(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  warmStartWide(blocks, begin, end, bodies);
}
void solveWideVl(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  solveWide(blocks, begin, end, bodies, s);
}
#endif

}  // namespace sim::world::soft

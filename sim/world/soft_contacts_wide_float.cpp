// soft_step's float passes (soft_contacts_float_lanes.h) compiled with -mavx2 where the compiler
// targets x86-64 (sim/CMakeLists.txt); elsewhere the same code in the target's own vectors.
#include "sim/world/soft_contacts_float_lanes.h"

namespace sim::world::soft {

void warmStartWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  for (int i = begin; i < end; ++i) warmStartBlock<WideFloatLanes>(blocks[i], bodies, 0);
}

void solveWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i) solveBlock<WideFloatLanes>(blocks[i], bodies, s, 0);
}

}  // namespace sim::world::soft

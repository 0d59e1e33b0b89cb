// soft_step's contact passes one lane at a time: the path for processors without AVX2, the
// overflow contacts (which may share bodies within a block) and the reference the wide path is
// tested against
#include "sim/world/soft_contacts_kernel.h"

namespace sim::world::soft {
namespace {

struct ScalarLane {
  using V = double;
  static V load(const Lanes& x, int lane) { return x.l[lane]; }
  static void store(Lanes& x, int lane, V v) { x.l[lane] = v; }
  static V splat(double v) { return v; }
  static bool greater(V a, V b) { return a > b; }
  static V select(bool m, V a, V b) { return m ? a : b; }
  static V max(V a, V b) { return a < b ? b : a; }
  static V min(V a, V b) { return b < a ? b : a; }
  static BodyLanes<V> gather(const BodyState* bodies, const int* index, int lane) {
    const BodyState& b = bodies[index[lane]];
    return {b.vx, b.vy, b.w, b.dpx, b.dpy, b.qc, b.qs};
  }
  static void scatter(BodyState* bodies, const int* index, int lane, const BodyLanes<V>& v) {
    BodyState& b = bodies[index[lane]];
    b.vx = v.vx, b.vy = v.vy, b.w = v.w;
  }
};

}  // namespace

void warmStartScalar(ContactBlock* blocks, int begin, int end, BodyState* bodies) {
  for (int i = begin; i < end; ++i)
    for (int lane = 0; lane < kLanes; ++lane) warmStartBlock<ScalarLane>(blocks[i], bodies, lane);
}

void solveScalar(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i)
    for (int lane = 0; lane < kLanes; ++lane) solveBlock<ScalarLane>(blocks[i], bodies, s, lane);
}

// asked here, outside the -mavx2 unit, so that nothing of it runs on a processor without AVX2
bool wideAvailable() {
#if defined(RIGIDREEL_WIDE_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return true;
#endif
}

bool wide512Available() {
#if defined(RIGIDREEL_WIDE_AVX512)
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  return avx512;
#else
  return false;
#endif
}

}  // namespace sim::world::soft

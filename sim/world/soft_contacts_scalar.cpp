// soft_step's contact passes one lane at a time: the path for processors without AVX2, the
// overflow contacts (which may share bodies within a block) and the reference the wide path is
// tested against
#include "sim/world/soft_contacts_kernel.h"

namespace sim::world::soft {
namespace {

template <class Number>
struct ScalarLane {
  using T = Number;
  using V = T;
  static V load(const LanesOf<T>& x, int lane) { return x.l[lane]; }
  static void store(LanesOf<T>& x, int lane, V v) { x.l[lane] = v; }
  static V splat(double v) { return static_cast<T>(v); }
  static bool greater(V a, V b) { return a > b; }
  static bool touchesStatic(const int* a, const int* b, int dummy, int lane) { return a[lane] == dummy || b[lane] == dummy; }
  static V select(bool m, V a, V b) { return m ? a : b; }
  static V max(V a, V b) { return a < b ? b : a; }
  static V min(V a, V b) { return b < a ? b : a; }
  static BodyLanes<V> gather(const BodyStateOf<T>* bodies, const int* index, int lane) {
    const BodyStateOf<T>& b = bodies[index[lane]];
    return {b.vx, b.vy, b.w, b.dpx, b.dpy, b.qc, b.qs, b.invMass};
  }
  static void scatter(BodyStateOf<T>* bodies, const int* index, int lane, const BodyLanes<V>& v) {
    BodyStateOf<T>& b = bodies[index[lane]];
    b.vx = v.vx, b.vy = v.vy, b.w = v.w;
  }
};

template <class T>
void warmStartLanes(ContactBlockOf<T>* blocks, int begin, int end, BodyStateOf<T>* bodies) {
  for (int i = begin; i < end; ++i)
    for (int lane = 0; lane < kLanesOf<T>; ++lane) warmStartBlock<ScalarLane<T>>(blocks[i], bodies, lane);
}

template <class T>
void solveLanes(ContactBlockOf<T>* blocks, int begin, int end, BodyStateOf<T>* bodies, const PassSettings& s) {
  for (int i = begin; i < end; ++i)
    for (int lane = 0; lane < kLanesOf<T>; ++lane) solveBlock<ScalarLane<T>>(blocks[i], bodies, s, lane);
}

}  // namespace

void warmStartScalar(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies) {
  warmStartLanes(blocks, begin, end, bodies);
}
void warmStartScalar(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies) {
  warmStartLanes(blocks, begin, end, bodies);
}
void solveScalar(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s) {
  solveLanes(blocks, begin, end, bodies, s);
}
void solveScalar(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s) {
  solveLanes(blocks, begin, end, bodies, s);
}

}  // namespace sim::world::soft

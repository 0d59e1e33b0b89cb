// soft_step's contact constraints laid out for the machine (Box2D v3's contact_solver.c, its wide
// constraints; Catto, "SIMD Matters", 2024; written anew here): the bodies' solver state in one
// flat array of records, the contacts of a set (contact_colors.h) packed into blocks, each number
// of a block stored side by side, one lane per contact, so that one block is solved in SIMD lanes.
// Each number of a block is 64 bytes, one AVX-512 register: in doubles (sim: {precision: double},
// the default) eight lanes, or two halves in AVX2's four; in floats (precision: float, as Box2D v3
// solves) sixteen, or two halves in AVX2's eight. The scalar path solves the same blocks lane by
// lane in the same order with the same operations: since the contacts of a block touch disjoint
// bodies, both give the same state to the bit (tests/sim/world/soft_contacts_test.cpp).
//
// No Eigen and no standard library templates here: the wide path is compiled with -mavx2 and must
// share no inline function with the rest of the program.
#pragma once

namespace sim::world::soft {

// a block's lanes: as many numbers as one 64-byte AVX-512 register holds (eight doubles, sixteen
// floats). Within a set the contacts touch disjoint bodies, so the state is the same to the bit for
// any grouping of a set into blocks
template <class T>
inline constexpr int kLanesOf = 64 / static_cast<int>(sizeof(T));

// a body during the substeps: velocity, inverse mass, and where it has moved since the step began
// (position delta dp, rotation delta dq as cos and sin); static bodies all share one record of
// zeros. One record is one register: 64 bytes of doubles, 32 of floats. (The inverse mass rides in
// the record, which every pass reads whole, rather than in two numbers of every block: 1-4 % of a
// step on the 5,050-box pyramid)
template <class T>
struct alignas(8 * sizeof(T)) BodyStateOf {
  T vx = 0, vy = 0, w = 0, invMass = 0;
  T dpx = 0, dpy = 0, qc = 1, qs = 0;
};

// a block's numbers, one per lane
template <class T>
struct alignas(64) LanesOf {
  T l[kLanesOf<T>] = {};
};

// one manifold point in a block's lanes; a lane without a second point has zero masses, so its
// impulses stay zero
template <class T>
struct PointLanesOf {
  LanesOf<T> rAx, rAy, rBx, rBy;  // lever arms from the centers of mass, fixed at the step's start
  LanesOf<T> baseSeparation;      // separation at the start less n · (rA − rB): the moving anchors add to it
  LanesOf<T> normalMass, tangentMass;
  LanesOf<T> normalImpulse, tangentImpulse;  // accumulated, warm started
  LanesOf<T> totalNormalImpulse;             // over the step's substeps
};

// a block's contacts, of one set (or of the overflow, solved lane by lane)
template <class T>
struct ContactBlockOf {
  int a[kLanesOf<T>] = {}, b[kLanesOf<T>] = {};  // BodyState indices, side by side
  LanesOf<T> nx, ny;                             // normal from B to A
  LanesOf<T> invInertiaA, invInertiaB;
  LanesOf<T> friction;
  PointLanesOf<T> p[2];
};

// a soft constraint's coefficients for a spring over a substep (Box2D v3's b2Softness)
struct Softness {
  double biasRate = 0.0, massScale = 1.0, impulseScale = 0.0;
};

// what a pass needs besides the blocks
struct PassSettings {
  double invH = 0.0;          // 1 / substep
  double maxPushSpeed = 0.0;  // the soft push's bound, m/s
  bool useBias = true;        // false: relax (rigid, no push)
  bool accumulate = false;    // the substep's last pass: each point's impulse added to its total
  // the soft constraint: `stiff` for a lane that touches the static record `staticIndex` (a static
  // body), `soft` for the others; chosen in the lanes, where three numbers of each block were read
  // (5,050-box pyramid: 4 % of a step in floats, 5 % in doubles)
  Softness soft, stiff;
  int staticIndex = 0;
};

// the passes over blocks [begin, end), lane by lane (scalar), half a block at once (wide: AVX2's
// four doubles or eight floats, the two halves interleaved) or a whole block in one AVX-512
// register (wide512: eight doubles or sixteen floats, two blocks of a set interleaved:
// soft_contacts_pair.h)
void warmStartScalar(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies);
void warmStartScalar(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies);
void solveScalar(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s);
void solveScalar(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s);
void warmStartWide(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies);
void warmStartWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies);
void solveWide(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s);
void solveWide(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s);
void warmStartWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies);
void warmStartWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies);
void solveWide512(ContactBlockOf<double>* blocks, int begin, int end, BodyStateOf<double>* bodies, const PassSettings& s);
void solveWide512(ContactBlockOf<float>* blocks, int begin, int end, BodyStateOf<float>* bodies, const PassSettings& s);
// (which of them this processor runs: sim/core/simd_support.h)

}  // namespace sim::world::soft

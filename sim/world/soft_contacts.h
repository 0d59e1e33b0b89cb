// soft_step's contact constraints laid out for the machine (Box2D v3's contact_solver.c, its wide
// constraints; Catto, "SIMD Matters", 2024; written anew here): the bodies' solver state in one
// flat array of 64-byte records, the contacts of a set (contact_colors.h) packed eight to a
// block, each number of a block stored as eight doubles side by side, so that one block is solved
// in the eight lanes of an AVX-512 register, or as two halves in AVX2's four (Box2D v3 solves
// eight floats in AVX2; eight doubles take AVX-512's width). The scalar path solves the same blocks lane by lane in
// the same order with the same operations: since the contacts of a block touch disjoint bodies,
// both give the same state to the bit (tests/world/soft_contacts_test.cpp).
//
// No Eigen and no standard library templates here: the wide path is compiled with -mavx2 and must
// share no inline function with the rest of the program.
#pragma once

namespace sim::world::soft {

constexpr int kLanes = 8;

// a body during the substeps: velocity, and where it has moved since the step began (position
// delta dp, rotation delta dq as cos and sin); static bodies all share one record of zeros
struct alignas(64) BodyState {
  double vx = 0.0, vy = 0.0, w = 0.0, unused = 0.0;
  double dpx = 0.0, dpy = 0.0, qc = 1.0, qs = 0.0;
};

// eight doubles, one per lane
struct alignas(64) Lanes {
  double l[kLanes] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

// one manifold point in eight lanes; a lane without a second point has zero masses, so its
// impulses stay zero
struct PointLanes {
  Lanes rAx, rAy, rBx, rBy;  // lever arms from the centers of mass, fixed at the step's start
  Lanes baseSeparation;      // separation at the start less n · (rA − rB): the moving anchors add to it
  Lanes normalMass, tangentMass;
  Lanes normalImpulse, tangentImpulse;  // accumulated, warm started
  Lanes totalNormalImpulse;             // over the step's substeps
};

// eight contacts of one set (or of the overflow, solved lane by lane)
struct ContactBlock {
  int a[kLanes] = {0, 0, 0, 0, 0, 0, 0, 0}, b[kLanes] = {0, 0, 0, 0, 0, 0, 0, 0};  // BodyState indices
  Lanes nx, ny;                                                                    // normal from B to A
  Lanes invMassA, invInertiaA, invMassB, invInertiaB;
  Lanes friction;
  Lanes biasRate, massScale, impulseScale;  // the soft constraint (static contacts stiffer)
  PointLanes p[2];
};

// what a pass needs besides the blocks
struct PassSettings {
  double invH = 0.0;          // 1 / substep
  double maxPushSpeed = 0.0;  // the soft push's bound, m/s
  bool useBias = true;        // false: relax (rigid, no push)
  bool accumulate = false;    // the substep's last pass: each point's impulse added to its total
};

// the passes over blocks [begin, end), lane by lane (scalar), four lanes at once (wide: AVX2) or
// eight (wide512: AVX-512)
void warmStartScalar(ContactBlock* blocks, int begin, int end, BodyState* bodies);
void solveScalar(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s);
void warmStartWide(ContactBlock* blocks, int begin, int end, BodyState* bodies);
void solveWide(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s);
void warmStartWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies);
void solveWide512(ContactBlock* blocks, int begin, int end, BodyState* bodies, const PassSettings& s);
// whether this processor runs the wide path (AVX2) and the wide512 one (AVX-512F), asked once at
// run time
bool wideAvailable();
bool wide512Available();

}  // namespace sim::world::soft

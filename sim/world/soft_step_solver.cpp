// The `soft_step` method: Box2D v3's solver as Erin Catto describes it ("Solver2D", 2024; Solver2D's
// solve_soft_step.c, Box2D v3's contact_solver.c, solver.c and constraint_graph.c; written anew
// here). The step is cut into `substeps`; each integrates the velocities, solves every contact once
// as a soft constraint (a spring of the scene's contact_hertz, by default kContactHertz, with
// damping ratio kContactDampingRatio, relative to the substep, whose push-out speed is bounded),
// integrates the positions, and solves the contacts once more without the push (relax), so that
// the push does not stay in the bodies as energy. Restitution is applied once after the substeps,
// from the normal velocity before them. Contacts are found once per step, warm started by feature
// id, with Coulomb friction; a point with a gap is a speculative contact that may close it but not
// overrun it. There is no position pass: the soft push is the correction. Forces act per substep
// by symplectic Euler, whatever the scene's integrator.
//
// Laid out for the machine as v3 is: the bodies' solver state in one flat array (soft_contacts.h),
// the contacts prepared once per step into blocks (eight doubles or sixteen floats), sorted into sets (contact_colors.h)
// so that each block is solved in SIMD lanes; the colouring is kept while the touching pairs stay
// the same.
#include <algorithm>
#include <cmath>
#include <memory>

#include "sim/collision/impulse.h"
#include "sim/core/simd_support.h"
#include "sim/world/contact_colors.h"
#include "sim/world/methods.h"
#include "sim/world/soft_contacts.h"
#include "sim/world/step_turn.h"
#include "sim/world/worker_pool.h"
#include "sim/world/world.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

namespace {

constexpr double kPi = 3.14159265358979323846;

using soft::Softness;

// a soft constraint's coefficients for a spring of `hertz` and damping ratio `zeta` over a substep
// h (Box2D v3's b2MakeSoft; Catto, "Solver2D": soft step)
Softness makeSoft(double hertz, double zeta, double h) {
  const double omega = 2.0 * kPi * hertz;
  const double a1 = 2.0 * zeta + h * omega, a2 = h * omega * a1, a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

// 1 / m_eff⁻¹ along d, or 0 where nothing can move (two static bodies), in T: in floats the
// reciprocal of the float (a float division: the double one was a sixth of the float preparation)
template <class T = double, class Bd>
T effectiveMass(const Bd& a, const Bd& b, const Vec2& rA, const Vec2& rB, const Vec2& d) {
  const T k = static_cast<T>(inverseEffectiveMassAt(a, b, rA, rB, d));
  return k > 0 ? T(1) / k : T(0);
}

// Contacts are found once per step, so a point the step will close must be found at its start: the
// margin reaches as far as the fastest body travels in the step (a speculative contact closes its
// gap and no more). With the fixed 1 cm margin, rows of Box2D's dropped pyramid landing at 2.2 m/s
// sank 2.7 cm before they were seen and the pile bulged 0.28 m; with this margin 0.041 m
// (rigidreel_stack_bench --method soft_step --layout pyramid:20:dropped).
double speculativeMargin(const World& world, double h) {
  // (the largest squared speed, then one square root: the same number, a root a body fewer)
  double fastest = 0.0;
  for (const Body& b : world.bodies)
    if (!b.isStatic) fastest = std::max(fastest, b.v.squaredNorm());
  return settings::kContactMargin + h * std::sqrt(fastest);
}

// where a contact sits among the blocks
struct Slot {
  int block = 0, lane = 0;
};

// what the preparation reads of a body, side by side (a Body spreads them over its 208 bytes)
struct Moving {
  Vec2 x, v;
  double omega, invMass, invInertia;
  bool isStatic;
};

// a manifold point's lever arms as the impulse helpers read them
struct LeverArms {
  Vec2 rA, rB;
};

// T: the numbers of the contact solve, double or float (sim: {precision})
template <class T>
class SoftStepSolver final : public Method {
  using ContactBlock = soft::ContactBlockOf<T>;
  using BodyState = soft::BodyStateOf<T>;
  static constexpr int kLanes = soft::kLanesOf<T>;

 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<SoftStepSolver>(*this); }

  // Box2D v3's stages (solver.c's b2SolverStage): the contacts found and prepared once; per
  // substep the velocities, warm start, the soft solve, the positions and the relax pass;
  // restitution once after them all; the impulses kept for the next step
  void step(World& world, const TimeStep& step) override {
    // the contacts where the bodies are now, carrying over last step's impulses
    WorkerPool& threads = shares(world) ? pool(world.def().threads) : solo_.p;
    world.findContacts(speculativeMargin(world, step.h), fresh_, &threads);
    std::swap(world.contacts, fresh_);
    const double h = step.h / world.def().substeps;
    const bool kept = beginStep(world, h, threads.size());
    // one task from the preparation to the impulses kept, the threads meeting between its stages:
    // a task of its own for each woke the other threads three times a step instead of once. The
    // substeps split every stage between the threads, which meet after each stage and each set of
    // contacts; restitution, when a contact has it, changes impulses before they are kept
    threads.run([&](int t) {
      const Share share{t, threads.size()};
      prepare(world, h, kept, share, threads);
      threads.sync();
      substeps(world, step, share, threads);
      threads.sync();
      storeBodies(world, share);
      if (!bouncy_) storeImpulses(world, share);
    });
    // restitution once, from the velocity before the substeps; the impulses kept, the impacts
    // recorded
    if (bouncy_) {
      applyRestitution(world);
      threads.run([&](int t) { storeImpulses(world, Share{t, threads.size()}); });
    }
    recordImpacts(world, step.end());
  }

 private:
  void substeps(const World& world, const TimeStep& step, const Share& share, WorkerPool& threads) {
    const int n = world.def().substeps;
    const double h = step.h / n;
    // the totals serve restitution and the impact records alone: a pile at rest needs neither
    const bool totals = bouncy_ || std::find(approaching_.begin(), approaching_.end(), 1) != approaching_.end();
    for (int k = 0; k < n; ++k) {
      integrateVelocities(world, step, h, share, threads);
      threads.sync();
      warmStart(share, threads);
      solve(h, true, false, share, threads);
      integratePositions(h, share);
      threads.sync();
      static_assert(settings::kRelaxIterations >= 1, "the totals are added in the last relax pass");
      // the last relax pass adds each point's impulse to the step's total as it goes
      for (int r = 0; r < settings::kRelaxIterations; ++r)
        solve(h, false, totals && r + 1 == settings::kRelaxIterations, share, threads);
    }
  }

  // whether the step is large enough for sim: threads to share it (settings.h: kContactsPerThread),
  // judged by last step's contacts
  bool shares(const World& world) const {
    const WorldDef& def = world.def();
    const int perThread = def.contactsPerThread > 0 ? def.contactsPerThread : settings::kContactsPerThread;
    return def.threads > 1 && world.contacts.size() >= static_cast<size_t>(perThread) * static_cast<size_t>(def.threads - 1);
  }

  // the pool of `threads` threads, made again when the count changes (a clone starts with none)
  WorkerPool& pool(int threads) {
    if (!pool_.p || pool_.p->size() != std::max(threads, 1)) pool_.p = std::make_unique<WorkerPool>(threads);
    return *pool_.p;
  }

  // the sets of the contacts, unless the touching pairs are those of last step, and each
  // contact's slot: the overflow's blocks first, then each set's, a set's last block padded
  // with lanes that touch only the static record
  // Returns whether they were made anew.
  bool arrange(const World& world) {
    const std::vector<Contact>& contacts = world.contacts;
    // (the world says when it found last step's pairs again: then there is no list to compare)
    bool same = contacts.size() == pairs_.size();
    if (same && world.contactPairsKept()) return false;
    for (size_t i = 0; same && i < contacts.size(); ++i) same = pairs_[i].a == contacts[i].a && pairs_[i].b == contacts[i].b;
    if (same) return false;
    pairs_.resize(contacts.size());
    bouncy_ = false;
    for (size_t i = 0; i < contacts.size(); ++i) {
      const Contact& c = contacts[i];
      pairs_[i] = {c.a, c.b, world.bodies[c.a].isStatic, world.bodies[c.b].isStatic};
      bouncy_ = bouncy_ || c.restitution != 0.0;
    }
    colorContacts(pairs_, static_cast<int>(world.bodies.size()), colors_);
    slots_.assign(contacts.size(), Slot{});
    ranges_.clear();
    padded_.clear();
    int block = 0;
    auto place = [&](const std::vector<int>& members) {
      const int first = block;
      for (size_t j = 0; j < members.size(); ++j)
        slots_[members[j]] = {first + static_cast<int>(j) / kLanes, static_cast<int>(j) % kLanes};
      block = first + static_cast<int>((members.size() + kLanes - 1) / kLanes);
      ranges_.push_back({first, block});
      if (members.size() % kLanes != 0) padded_.push_back(block - 1);
    };
    place(colors_.overflow);
    for (const std::vector<int>& set : colors_.sets) place(set);
    blockCount_ = block;
    return true;
  }

  // the widest SIMD the passes may use, at most `allowed` (WorldDef::simdWidth): 8 AVX-512, 4 AVX2, 1
  // none; a whole block at once in AVX-512 (eight doubles, sixteen floats), half of one in AVX2, or
  // one lane
  static int laneWidth(int allowed) { return allowed >= 8 && avx512Available() ? 8 : allowed >= 4 && avx2Available() ? 4 : 1; }

  // the blocks and the bodies' arrays sized for this step, which `threads` share (on one thread, before the task)
  // Returns whether each lane keeps last step's pair, masses and friction.
  bool beginStep(World& world, double h, int threads) {
    const bool arranged = arrange(world);
    width_ = laneWidth(world.def().simdWidth);
    const int dummy = static_cast<int>(world.bodies.size());  // the static bodies' shared record
    // Box2D v3: contactHertz = min(contactHertz, 0.25 × substep rate); static contacts twice as stiff
    const double hertz = std::min(world.def().contactHertz, settings::kContactHertzPerSubstepRate / h);
    const Softness soft = makeSoft(hertz, settings::kContactDampingRatio, h);
    const Softness staticSoft = makeSoft(2.0 * hertz, settings::kContactDampingRatio, h);
    // the same pairs in the same lanes as last step: each lane's bodies, masses and friction are in
    // it already, and the padded lanes are still zeros
    const bool kept = !arranged && dummy == dummy_;
    soft_ = soft, staticSoft_ = staticSoft, dummy_ = dummy;
    blocks_.resize(blockCount_);
    vnBefore_.resize(2 * world.contacts.size());
    points_.resize(world.contacts.size());
    approaching_.assign(threads, 0);
    sizeBodies(world);
    return kept;
  }

  // each thread its share of the padded blocks cleared (the lanes no contact fills touch only
  // the static record, with zero masses), then its share of the contacts, each of which writes
  // every number of its own lane
  void prepare(const World& world, double h, bool kept, const Share& share, WorkerPool& threads) {
    const int dummy = static_cast<int>(world.bodies.size());
    loadBodies(world, h, share);
    const auto [firstPadded, lastPadded] = share.of(0, kept ? 0 : static_cast<int>(padded_.size()));
    for (int k = firstPadded; k < lastPadded; ++k) {
      ContactBlock& blk = blocks_[padded_[k]];
      blk = ContactBlock{};
      for (int l = 0; l < kLanes; ++l) blk.a[l] = blk.b[l] = dummy;
    }
    threads.sync();
    const auto [first, last] = share.of(0, static_cast<int>(world.contacts.size()));
    for (int i = first; i < last; ++i) prepareContact(world, i, !kept, share.t);
  }

  // one contact into its lane: normal, masses, friction, and each point's anchors and impulses
  // (the numbers that stay while the lane keeps its pair only when `constants`; on thread `share`)
  void prepareContact(const World& world, int i, bool constants, int share) {
    const int dummy = static_cast<int>(world.bodies.size());
    const Contact& c = world.contacts[i];
    const Moving &a = moving_[c.a], &b = moving_[c.b];
    ContactBlock& blk = blocks_[slots_[i].block];
    const int l = slots_[i].lane;
    const Vec2 n = c.manifold.normal, t = tangentOf(n);
    if (constants) {
      blk.a[l] = a.isStatic ? dummy : c.a, blk.b[l] = b.isStatic ? dummy : c.b;
      blk.invInertiaA.l[l] = a.invInertia, blk.invInertiaB.l[l] = b.invInertia;
      blk.friction.l[l] = c.friction;
    }
    blk.nx.l[l] = n.x(), blk.ny.l[l] = n.y();
    points_[i] = static_cast<char>(c.manifold.count);
    for (int k = 0; k < c.manifold.count; ++k) {
      soft::PointLanesOf<T>& p = blk.p[k];
      const ManifoldPoint& m = c.manifold.points[k];
      const LeverArms r{m.point - a.x, m.point - b.x};
      p.rAx.l[l] = r.rA.x(), p.rAy.l[l] = r.rA.y(), p.rBx.l[l] = r.rB.x(), p.rBy.l[l] = r.rB.y();
      // the separation at the start, less what the anchors' own motion will add to it
      p.baseSeparation.l[l] = m.separation - n.dot(r.rA - r.rB);
      p.normalMass.l[l] = effectiveMass<T>(a, b, r.rA, r.rB, n);
      p.tangentMass.l[l] = effectiveMass<T>(a, b, r.rA, r.rB, t);
      p.normalImpulse.l[l] = c.state[k].normalImpulse;
      p.tangentImpulse.l[l] = c.state[k].tangentImpulse;
      p.totalNormalImpulse.l[l] = 0.0;
      vnBefore_[2 * i + k] = n.dot(relativeVelocityAt(a, b, r));
      if (vnBefore_[2 * i + k] < -settings::kRestitutionThreshold) approaching_[share] = 1;
    }
    // a missing second point: zero masses and impulses, so that it never pushes
    for (int k = c.manifold.count; k < 2; ++k) {
      soft::PointLanesOf<T>& p = blk.p[k];
      for (soft::LanesOf<T>* x : {&p.rAx, &p.rAy, &p.rBx, &p.rBy, &p.baseSeparation, &p.normalMass, &p.tangentMass,
                                  &p.normalImpulse, &p.tangentImpulse, &p.totalNormalImpulse})
        x->l[l] = 0;
    }
  }

  // the bodies' solver state from the world: velocities, nothing moved yet
  // (and what the preparation reads of each; under gravity alone, what it adds to each body's
  // velocity in a substep h: zero to a static or sleeping body, which is not integrated)
  // (the arrays sized first, on one thread; then each thread its share of the bodies)
  void sizeBodies(const World& world) {
    const size_t n = world.bodies.size();
    states_.resize(n + 1);
    states_[n] = BodyState{};
    x_.resize(n), angle_.resize(n), turned_.resize(n), moving_.resize(n);
    gravityDv_.resize(world.def().forces.gravityOnly() ? n : 0);
  }
  void loadBodies(const World& world, double h, const Share& share) {
    const std::vector<Body>& bodies = world.bodies;
    const bool gravity = world.def().forces.gravityOnly();
    const auto [first, last] = share.of(0, static_cast<int>(bodies.size()));
    for (int i = first; i < last; ++i) {
      const Body& b = bodies[i];
      moving_[i] = {b.x, b.v, b.omega, b.invMass, b.invInertia, b.isStatic};
      x_[i] = b.x, angle_[i] = b.angle, turned_[i] = 0.0;
      BodyState& s = states_[i];
      s = BodyState{};
      if (gravity) gravityDv_[i] = Vec2::Zero();
      if (b.isStatic) continue;
      s.vx = b.v.x(), s.vy = b.v.y(), s.w = b.omega, s.invMass = static_cast<T>(b.invMass);
      if (gravity && !world.asleep(i)) gravityDv_[i] = h * Vec2(b.invMass * Vec2(b.mass * world.def().forces.gravity));
    }
  }

  void storeBodies(World& world, const Share& share) const {
    const auto [first, last] = share.of(0, static_cast<int>(world.bodies.size()));
    for (int i = first; i < last; ++i) {
      Body& b = world.bodies[i];
      if (b.isStatic) continue;
      const BodyState& s = states_[i];
      b.v = {double(s.vx), double(s.vy)}, b.omega = s.w, b.x = x_[i], b.angle = angle_[i];
    }
  }

  // v += h (f/m), ω += h τ/I with the forces at the substep's start (symplectic Euler); under
  // gravity alone the same numbers without assembling the forces
  void integrateVelocities(const World& world, const TimeStep& step, double h, const Share& share, WorkerPool& threads) {
    const std::vector<Body>& bodies = world.bodies;
    const auto [first, last] = share.of(0, static_cast<int>(bodies.size()));
    if (world.def().forces.gravityOnly()) {
      // (adding a zero leaves a static or sleeping body's velocity as it is, a zero)
      for (int i = first; i < last; ++i) states_[i].vx += gravityDv_[i].x(), states_[i].vy += gravityDv_[i].y();
      return;
    }
    // the forces of the whole world on the first thread, then each thread's bodies
    if (share.t == 0) {
      states_y_.resize(bodies.size());
      for (size_t i = 0; i < bodies.size(); ++i) {
        const BodyState& s = states_[i];
        states_y_[i] = {x_[i], angle_[i], Vec2(double(s.vx), double(s.vy)), double(s.w)};
      }
      world.rates(step.midpoint(), states_y_, rates_);
    }
    threads.sync();
    for (int i = first; i < last; ++i) {
      if (bodies[i].isStatic) continue;
      const Vec2 dv = h * rates_[i].vDot;
      states_[i].vx += dv.x(), states_[i].vy += dv.y();
      states_[i].w += h * rates_[i].omegaDot;
    }
  }

  // x += h v, θ += h ω; the deltas since the step began, for the separations (the rotation's
  // exactly: Box2D v3's cheaper normalised tangent step let the dropped 210-box pyramid end
  // 0.0501 m off its rest pose, against 0.0483 m)
  void integratePositions(double h, const Share& share) {
    const auto [first, last] = share.of(0, static_cast<int>(states_.size()) - 1);
    for (int i = first; i < last; ++i) {
      BodyState& s = states_[i];
      if (s.vx == 0 && s.vy == 0 && s.w == 0) continue;  // static, or at rest
      const double dx = h * s.vx, dy = h * s.vy, da = h * s.w;
      x_[i] += Vec2(dx, dy), angle_[i] += da;
      s.dpx += dx, s.dpy += dy;
      // one local angle, read once: a store to qc could alias turned_[i] (it once kept libm's cos
      // and sin from being one sincos: 5 % of a step on the 5,050-box pyramid)
      const double turned = turned_[i] += da;
      stepTurn(turned, s.qc, s.qs);
    }
  }

  // each pass: the overflow one contact after the other (on the first thread), then each set's
  // blocks, split between the threads, which meet after each set
  template <class Overflow, class Set>
  void pass(const Share& share, WorkerPool& threads, Overflow overflow, Set set) {
    for (size_t r = 0; r < ranges_.size(); ++r) {
      const auto [begin, end] = ranges_[r];
      if (begin == end) continue;  // (every thread skips it alike)
      if (r == 0) {
        if (share.t == 0) overflow(begin, end);
      } else {
        const auto [first, last] = share.of(begin, end);
        set(first, last);
      }
      threads.sync();
    }
  }

  void warmStart(const Share& share, WorkerPool& threads) {
    BodyState* bodies = states_.data();
    ContactBlock* blocks = blocks_.data();
    pass(
        share, threads, [&](int b, int e) { soft::warmStartScalar(blocks, b, e, bodies); },
        [&](int b, int e) {
          width_ == 8   ? soft::warmStartWide512(blocks, b, e, bodies)
          : width_ == 4 ? soft::warmStartWide(blocks, b, e, bodies)
                        : soft::warmStartScalar(blocks, b, e, bodies);
        });
  }

  void solve(double h, bool useBias, bool accumulate, const Share& share, WorkerPool& threads) {
    const soft::PassSettings s{1.0 / h, settings::kContactPushMaxSpeed, useBias, accumulate, soft_, staticSoft_, dummy_};
    BodyState* bodies = states_.data();
    ContactBlock* blocks = blocks_.data();
    pass(
        share, threads, [&](int b, int e) { soft::solveScalar(blocks, b, e, bodies, s); },
        [&](int b, int e) {
          width_ == 8   ? soft::solveWide512(blocks, b, e, bodies, s)
          : width_ == 4 ? soft::solveWide(blocks, b, e, bodies, s)
                        : soft::solveScalar(blocks, b, e, bodies, s);
        });
  }

  LeverArms armsOf(size_t contact, int k) const {
    const ContactBlock& blk = blocks_[slots_[contact].block];
    const int l = slots_[contact].lane;
    const soft::PointLanesOf<T>& p = blk.p[k];
    return {Vec2(double(p.rAx.l[l]), double(p.rAy.l[l])), Vec2(double(p.rBx.l[l]), double(p.rBy.l[l]))};
  }

  // restitution for points that arrived faster than the threshold and pushed (Box2D v3's
  // b2ApplyRestitution): the normal velocity brought to −e times the one before the step
  void applyRestitution(World& world) {
    if (!bouncy_) return;  // no pass over the contacts where none has restitution (a pile)
    std::vector<Body>& bodies = world.bodies;
    for (size_t i = 0; i < world.contacts.size(); ++i) {
      const Contact& c = world.contacts[i];
      if (c.restitution == 0.0) continue;
      Body &a = bodies[c.a], &b = bodies[c.b];
      ContactBlock& blk = blocks_[slots_[i].block];
      const int l = slots_[i].lane;
      const Vec2 n = c.manifold.normal;
      for (int k = 0; k < c.manifold.count; ++k) {
        soft::PointLanesOf<T>& p = blk.p[k];
        const double vnBefore = vnBefore_[2 * i + k];
        if (vnBefore > -settings::kRestitutionThreshold || p.totalNormalImpulse.l[l] == 0.0) continue;
        const LeverArms r = armsOf(i, k);
        const double vn = n.dot(relativeVelocityAt(a, b, r));
        const double impulse = p.normalImpulse.l[l];
        // the mass in doubles from the arms as stored (in floats: so that the law holds to a
        // double's round-off; in doubles it is the stored mass to the bit)
        const double lambda = -effectiveMass(a, b, r.rA, r.rB, n) * (vn + c.restitution * vnBefore);
        const double total = std::max(impulse + lambda, 0.0);
        applyAt(a, b, r, (total - impulse) * n);
        p.totalNormalImpulse.l[l] += total - impulse;
        p.normalImpulse.l[l] = total;
      }
    }
  }

  // the impulses kept for the next step's warm start: the thread's share of the contacts (their
  // counts of points read from points_: the contacts are 3 MB on the 5,050-box pyramid, and each
  // one's count sits a cache line apart from its impulses)
  void storeImpulses(World& world, const Share& share) const {
    const auto [first, last] = share.of(0, static_cast<int>(world.contacts.size()));
    for (int i = first; i < last; ++i) {
      Contact& c = world.contacts[i];
      const ContactBlock& blk = blocks_[slots_[i].block];
      const int l = slots_[i].lane;
      for (int k = 0; k < points_[i]; ++k) {
        c.state[k].normalImpulse = blk.p[k].normalImpulse.l[l];
        c.state[k].tangentImpulse = blk.p[k].tangentImpulse.l[l];
      }
    }
  }

  // the impacts of the step recorded, in the contacts' order (the approach speeds read first: a
  // pile at rest has none, and its contacts are not touched again; nor its speeds, when prepare
  // saw none)
  void recordImpacts(World& world, double t) const {
    if (std::find(approaching_.begin(), approaching_.end(), 1) == approaching_.end()) return;
    for (size_t i = 0; i < world.contacts.size(); ++i) {
      for (int k = 0; k < 2; ++k) {
        const double vnBefore = vnBefore_[2 * i + k];
        if (vnBefore >= -settings::kRestitutionThreshold) continue;
        const Contact& c = world.contacts[i];
        if (k >= c.manifold.count) continue;
        const ContactBlock& blk = blocks_[slots_[i].block];
        const int l = slots_[i].lane;
        const soft::PointLanesOf<T>& p = blk.p[k];
        const double total = p.totalNormalImpulse.l[l];
        if (total <= 0.0) continue;
        const LeverArms r = armsOf(i, k);
        const Vec2 n = c.manifold.normal;
        ImpactRecord rec{t, c.a, c.b, c.manifold.points[k].point, n, total, p.tangentImpulse.l[l]};
        rec.vnBefore = vnBefore;
        rec.vnAfter = n.dot(relativeVelocityAt(world.bodies[c.a], world.bodies[c.b], r));
        world.impacts.push_back(rec);
      }
    }
  }

  int width_ = 1;                   // the sets' blocks whole (8), by halves (4) or lane by lane (1): laneWidth
  bool bouncy_ = false;             // some contact has restitution (the pairs' bodies fix it)
  std::vector<ColoredPair> pairs_;  // the pairs the colouring was made for
  ContactColors colors_;
  std::vector<Slot> slots_;                  // each contact's block and lane
  std::vector<std::pair<int, int>> ranges_;  // blocks of the overflow, then of each set
  std::vector<int> padded_;                  // the blocks with lanes no contact fills (a set's last)
  int blockCount_ = 0;
  std::vector<ContactBlock> blocks_;
  Softness soft_, staticSoft_;     // this step's, of a lane without a static body and of one with one
  int dummy_ = -1;                 // the static record's index the blocks' lanes name
  std::vector<double> vnBefore_;   // each point's normal velocity before the step (restitution)
  std::vector<char> points_;       // each contact's count of points
  std::vector<char> approaching_;  // per thread: one of its points comes faster than restitution's threshold
  std::vector<BodyState> states_;  // the bodies during the substeps, then the static record
  std::vector<Vec2> x_;            // positions and angles during the substeps
  std::vector<double> angle_;
  std::vector<double> turned_;   // each body's rotation since the step began
  std::vector<Vec2> gravityDv_;  // under gravity alone, each body's velocity change in a substep
  std::vector<Moving> moving_;   // the bodies as the preparation reads them
  States states_y_;              // scratch of integrateVelocities, for forces other than gravity
  std::vector<Contact> fresh_;   // the contacts found, then last step's (their storage reused)
  Rates rates_;
  // the threads of sim: threads (none copied: a clone makes its own)
  struct PoolHandle {
    std::unique_ptr<WorkerPool> p;
    PoolHandle() = default;
    PoolHandle(const PoolHandle&) {}
    PoolHandle& operator=(const PoolHandle&) { return *this; }
  } pool_;
  // a step too small to share runs here, on the caller's thread alone (a pool of one starts no thread)
  struct SoloHandle {
    WorkerPool p{1};
    SoloHandle() = default;
    SoloHandle(const SoloHandle&) {}
    SoloHandle& operator=(const SoloHandle&) { return *this; }
  } solo_;
};

}  // namespace

std::unique_ptr<Method> makeSoftStepSolver(Precision precision) {
  if (precision == Precision::Float) return std::make_unique<SoftStepSolver<float>>();
  return std::make_unique<SoftStepSolver<double>>();
}

}  // namespace sim::world

// Every tunable number of the simulator, with its unit and why it has the value it has.
// Scene units are the user's (meters, kilograms, seconds by convention); lengths below that are
// relative are marked so.
#pragma once

namespace sim::core::settings {

// default fixed time step, s: 1 ms resolves the motion of a scene 1 m across to plot accuracy
inline constexpr double kDefaultDt = 1e-3;

// default simulated duration, s
inline constexpr double kDefaultDuration = 1.0;

// default bound on the steps of one run (duration / dt), and on all the runs of one stability
// search together: one falling box takes 4.7 s of CPU for 10⁸ steps (`rigidreel check` at dt 1e-6
// over 100 s), a scene of many bodies far longer, so the bound stops a mistyped dt within seconds
// to minutes, not after years; a scene that needs more says so with `sim: {max_steps: N}`
inline constexpr double kDefaultMaxSteps = 1e8;

// default bound on the bodies of one scene (sim: max_bodies): 100,000 circles load in 5.4 s of CPU
// and 570 MB (`simulate --until 0`, README.md: Limits); a scene past it is most likely generated
// wrong, and one that is not says so with `sim: {max_bodies: N}`
inline constexpr int kDefaultMaxBodies = 100000;

// default bound on the vertices of one polygon (sim: max_vertices): two polygons cost vertices ×
// vertices per step (sim/collision/collide.cpp tries every edge of one against every vertex of the
// other), and 1024 sides stay within 5·10⁻⁶ of the radius of their circle (the sagitta
// r·(1 − cos π/n)): more is a generated outline that meant a circle
inline constexpr int kDefaultMaxVertices = 1024;
// the most parts one body may have (sim: {max_parts: N}): each pair of parts is checked for overlap
// when the scene is read
inline constexpr int kDefaultMaxParts = 256;
// m per m of a body's size: parts of one body may overlap this much (round-off where they touch)
inline constexpr double kPartOverlapTolerance = 1e-9;

// default bound on a scene's forces, events and expect entries together (sim: max_entries): each is
// a few hundred bytes of definition and is looked up once per step or event; a million is far past
// any scene written by hand and well within memory
inline constexpr int kDefaultMaxEntries = 1000000;

// default density, kg/m² (area density in 2D), when neither density nor mass is given
inline constexpr double kDefaultDensity = 1.0;

// two times closer than this fraction of dt are the same instant (events on the step grid)
inline constexpr double kTimeSnap = 1e-9;

// polygon vertices must turn by more than this (relative to the squared size) to count as convex:
// collinear or repeated vertices are rejected instead of giving zero-length edges
inline constexpr double kPolygonTurnTolerance = 1e-12;

// a convex polygon's turns add up to 2π, rad; a star's to 4π or more: this slack takes atan2's
// round-off over many vertices and is still far below the 2π that tells the two apart
inline constexpr double kPolygonWindingTolerance = 1e-6;

// default absolute tolerance of an `expect` check (SI units of the checked quantity)
inline constexpr double kDefaultExpectTolerance = 1e-9;

}  // namespace sim::core::settings

namespace sim::core::settings {

// --- collisions ---

// contact points are kept while the surfaces are closer than this, m (Box2D: 2 × linear slop),
// so resting contacts do not flicker in and out from step to step
inline constexpr double kContactMargin = 0.01;

// the broad phase keeps each body's bounds enlarged by this, m, and pairs it anew only when it
// leaves them, so a pile at rest is not paired from scratch every step (Box2D's b2_aabbExtension)
inline constexpr double kBroadPhaseExtension = 0.1;

// a polygon pair keeps A's edge as the reference unless B's separates by more than this, m, so the
// manifold does not flip between two edges on near ties from step to step (Box2D's
// b2CollidePolygons: 0.1 × linear slop, 0.5 mm)
inline constexpr double kReferenceEdgeHysteresis = 0.05 * kContactMargin;

// the sequential solver's polygon pairs clip the incident edge to the reference edge's side planes
// moved out by this, m, so that an incident vertex a hair past the reference edge's end (a box on
// one as wide, turned by round-off) stays the point it was, with its feature id and so its warm
// start, instead of becoming a new point cut at the edge's end that starts cold on one side only
// (a column of four boxes whose top weighs 30 times each of the others held in place of
// collapsing, the arch's top sag 0.505 → 0.34 m). Box2D 2.4's b2CollidePolygons moves them out
// by the polygons' skin, b2_polygonRadius each: 1 cm past the rounded outline, 2 × linear slop
inline constexpr double kClipSideSlack = 0.01;

// penetration the sequential solver leaves uncorrected, m (Box2D's b2_linearSlop: 0.5 cm), so
// resting contacts do not jitter
inline constexpr double kLinearSlop = 0.005;

// fraction of the remaining penetration removed per position iteration (Box2D's b2_baumgarte)
inline constexpr double kPositionCorrection = 0.2;

// largest position correction in one iteration, m (Box2D's b2_maxLinearCorrection)
inline constexpr double kMaxLinearCorrection = 0.2;

// below this approach speed, m/s, the sequential solver applies no restitution, so that resting
// contacts settle instead of bouncing on the velocity one step of gravity gives them
// (Box2D's b2_velocityThreshold)
inline constexpr double kRestitutionThreshold = 1.0;

// sequential solver iterations, as Box2D 2.4's defaults
inline constexpr int kVelocityIterations = 8;
inline constexpr int kPositionIterations = 3;

// the position pass stops when the deepest point is within this, m (Box2D 2.4's
// b2ContactSolver::SolvePositionConstraints: 3 × linear slop)
inline constexpr double kPositionSolvedDepth = 3.0 * kLinearSlop;
// soft_step's contact recycling (sim: {recycle: true}): a pair keeps its manifold while B moved
// relative to A by less than this, m (Box2D v3's B2_CONTACT_RECYCLE_DISTANCE: 10 linear slops)
inline constexpr double kRecycleDistance = 10.0 * kLinearSlop;
// and neither body turned by more than acos of this since it was made (v3's 0.98: 11.5°)
inline constexpr double kRecycleCos = 0.98;

// the sequential solver solves a two-point manifold's normal impulses together (the 2×2 block)
// only while its condition number, estimated as K₁₁²/det K, is below this; nearer one point the
// block is left to the point-by-point sweep (Box2D 2.4's k_maxConditionNumber)
inline constexpr double kMaxConditionNumber = 1000.0;

// --- soft_step (Box2D v3's soft step; Catto, "Solver2D", 2024) ---

// substeps per step by default: each integrates velocities, solves the contacts once with their
// softness, integrates positions and relaxes once (Box2D v3's b2_defaultSubStepCount)
inline constexpr int kSubsteps = 4;

// contact stiffness, Hz, at most a quarter of the substep rate (Box2D v3's contactHertz: 30, and
// min(contactHertz, 0.25 × substep rate)); contacts with a static body twice as stiff (Solver2D);
// a scene may stiffen them (sim: contact_hertz), which the cap lets through only with more substeps
inline constexpr double kContactHertz = 30.0;
inline constexpr double kContactHertzPerSubstepRate = 0.25;

// contact damping ratio, relative to critical (Box2D v3's contactDampingRatio: 10, heavily damped,
// so a soft contact pushes out without bouncing)
inline constexpr double kContactDampingRatio = 10.0;

// the fastest a soft contact pushes overlapping bodies apart, m/s (Box2D v3's contactPushMaxVelocity)
inline constexpr double kContactPushMaxSpeed = 3.0;

// relax passes per substep: the contacts solved again without the soft push, so the push's speed
// does not stay in the bodies as energy (Box2D v3: one, useBias = false)
inline constexpr int kRelaxIterations = 1;

// --- sleeping (sim: {sleep: true}; Box2D 2.4's b2_linearSleepTolerance, b2_angularSleepTolerance
// and b2_timeToSleep, b2Island::Solve) ---

// a body slower than both of these counts as at rest, m/s and rad/s: Box2D's 1 cm/s and 2°/s, a
// hundredth of the speed a box reaches falling 5 cm (0.99 m/s) and above the creep of a settled pile
// under the stack solvers (soft_step's fastest body in the 5,050-box pyramid, 0.005 m/s)
inline constexpr double kSleepLinearSpeed = 0.01;
inline constexpr double kSleepAngularSpeed = 2.0 * 3.14159265358979323846 / 180.0;

// an island whose every body has been at rest this long falls asleep, s (Box2D's 0.5 s): longer
// than a bounce or a rocking box takes to turn round through zero speed
inline constexpr double kTimeToSleep = 0.5;
// the most threads sim: threads and --threads accept (each set of contacts is split between them)
inline constexpr int kMaxThreads = 64;
// soft_step's threads share a step only when it has this many contacts for each thread past the
// first; a smaller step runs on one (the same state). The threads meet about a hundred times a
// step. On this 2-core machine idle, a second thread first paid near 300 contacts (Box2D's packed
// pyramid of 105 boxes) and took a sixth to a quarter off at 600 (210 boxes); with a build busy on
// the other core it doubled the 210-box step, and first paid near 5,000 contacts in floats
// (rigidreel_stack_bench --layout pyramid:BASE:packed --method soft_step --recycle on --threads 1
// --threads 2 --contacts-per-thread 1)
inline constexpr int kContactsPerThread = 1000;

// default coefficients: restitution halfway between elastic and plastic, frictionless as in the
// notes
inline constexpr double kDefaultRestitution = 0.5;
inline constexpr double kDefaultFriction = 0.0;

// event method: a time of impact is found when the gap is below this fraction of the scene's size
inline constexpr double kImpactTolerance = 1e-12;

// event method: contacts within this fraction of the scene's size of touching at an impact are
// resolved together (simultaneous impacts)
inline constexpr double kTouchingTolerance = 1e-9;

// event method: a contact leaving an impact slower than this, m/s, becomes a resting contact
// (impacts would otherwise pile up in finite time: the Zeno behaviour of a bouncing ball)
inline constexpr double kRestingSpeed = 1e-6;

// event method: at most this many impacts in one step before giving up with an error
inline constexpr int kMaxImpactsPerStep = 10000;

// --- `auto`'s watch over the event method (contact_watch.h) ---

// a pair whose impacts come this many times within kRepeatWindow, each approaching slower than
// kRepeatSpeed, rattles rather than bounces: under gravity a bounce of 25 ms rises under 1 mm
// (g τ²/8), and below sequential's restitution threshold (1 m/s) no stack solver bounces either
inline constexpr int kRepeatedImpacts = 4;
inline constexpr double kRepeatWindow = 0.1;                   // s
inline constexpr double kRepeatSpeed = kRestitutionThreshold;  // m/s

// --- event method: time of impact (time_of_impact.h) ---

// the approach speed bound of conservative advancement is taken at the two ends of the span; under
// forces other than gravity the speed between them can be higher, so the bound is raised by this
// factor (a margin, not a proof: a stiff enough spring can exceed it); under gravity alone the
// speeds change linearly, and the ends bound them
inline constexpr double kApproachBoundMargin = 1.25;

// the first look-ahead out of a touching contact, as a fraction of the step: small enough to come
// before any next impact, doubled until the pair is clear of the touching band
inline constexpr double kLookAheadStart = 1e-12;

// the root bracket is not narrowed below this fraction of the step: a few units in the last place
// of a time near the step's length, where regula falsi can gain nothing more
inline constexpr double kImpactBracket = 1e-15;

// regula falsi (Illinois) iterations at most: it converges superlinearly, a few dozen reach
// kImpactTolerance; the bound only guards against a gap that never settles
inline constexpr int kMaxRefineIterations = 200;

// conservative advancement steps of one pair in one span at most, before the pair counts as not
// meeting: each step advances by gap / bound, so only a pair grazing at the tolerance comes near
inline constexpr int kMaxAdvancementIterations = 100000;

// --- event method: impacts and resting contact ---

// approaching slower than this, m/s, does not count as an impact: round-off after an impulse
// (a thousandth of kRestingSpeed)
inline constexpr double kApproachFloor = 1e-3 * kRestingSpeed;

// Gauss–Seidel sweeps over simultaneous impacts at most, before the motion goes on (what still
// approaches is found again as an impact at once): a guard, far above what a cradle needs
inline constexpr int kMaxImpactSweeps = 1000;

// two impacting points are solved together unless det K ≤ this × K₁₁ K₂₂ (relative): then the
// two points act as one and the fastest is answered alone
inline constexpr double kMinBlockDeterminant = 1e-12;

// a resting contact is kept, and its forces found, while the surfaces are within this many
// touching tolerances: wider than the touching band, so that round-off does not release it
inline constexpr double kRestingReach = 100.0;

// projected Gauss–Seidel sweeps for the resting contacts' forces: a fixed count, so that the
// forces (recomputed at every evaluation of the motion) are the same every run
inline constexpr int kRestingForceSweeps = 50;

// the smallest scene size, m: the event method's tolerances are fractions of the scene's size and
// must stay positive when every body is a point (circles of radius 0)
inline constexpr double kMinSceneSize = 1e-9;

}  // namespace sim::core::settings

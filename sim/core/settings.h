// Every tunable number of the simulator, with its unit and why it has the value it has.
// Scene units are the user's (meters, kilograms, seconds by convention); lengths below that are
// relative are marked so.
#pragma once

namespace sim::core::settings {

// default fixed time step, s: 1 ms resolves the motion of a scene 1 m across to plot accuracy
inline constexpr double kDefaultDt = 1e-3;

// default simulated duration, s
inline constexpr double kDefaultDuration = 1.0;

// default density, kg/m² (area density in 2D), when neither density nor mass is given
inline constexpr double kDefaultDensity = 1.0;

// two times closer than this fraction of dt are the same instant (events on the step grid)
inline constexpr double kTimeSnap = 1e-9;

// polygon vertices must turn by more than this (relative to the squared size) to count as convex:
// collinear or repeated vertices are rejected instead of giving zero-length edges
inline constexpr double kPolygonTurnTolerance = 1e-12;

// default absolute tolerance of an `expect` check (SI units of the checked quantity)
inline constexpr double kDefaultExpectTolerance = 1e-9;

}  // namespace sim::core::settings

namespace sim::core::settings {

// --- collisions ---

// contact points are kept while the surfaces are closer than this, m (Box2D: 2 × linear slop),
// so resting contacts do not flicker in and out from step to step
inline constexpr double kContactMargin = 0.01;

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

}  // namespace sim::core::settings

// Every tunable number of the simulator, with its unit and why it has the value it has.
// Scene units are the user's (meters, kilograms, seconds by convention); lengths below that are
// relative are marked so.
#pragma once

namespace sim::settings {

// default fixed time step, s: 1 ms resolves a 1 m lecture scene's motion to plot accuracy
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

}  // namespace sim::settings

// Time of impact: the first instant at which two moving shapes touch (Box2D's b2TimeOfImpact),
// found by conservative advancement (Mirtich 1996, "Impulse-based Dynamic Simulation of Rigid
// Body Systems"), a pure function of the two shapes and their motion.
//
// The gap s(τ) is collide()'s separation, a lower bound of the distance. No material point of A
// approaches B faster than the bound B = |v_a − v_b| + |ω_a| R_a + |ω_b| R_b, so the pair cannot
// touch before τ + s/B: advancing by s/B never passes the contact, at any speed. A secant probe
// through the last two gaps brackets the root early, and regula falsi (Illinois: Dowell and
// Jarratt 1971) polishes it from the side where the shapes do not overlap.
//
//   gap s(τ)
//     │●
//     │   ●              ●  the gap at each advancement step, s/B after the last: never past ╳
//     │      ●
//   0 ┼─────────●─╳──────── τ     ╳  the impact
//     │              ○               ○  a secant probe past it (s < 0): the root is bracketed
#pragma once

#include <functional>
#include <optional>

#include "sim/core/body.h"
#include "sim/core/math.h"
#include "sim/core/shape.h"

namespace sim::collision {

// where the two shapes are at τ
struct PosePair {
  sim::core::Pose a, b;
};

struct ToiInput {
  const sim::core::Shape* a = nullptr;
  const sim::core::Shape* b = nullptr;
  // the poses τ after the search starts: any motion (exact parabolas, an integrator's steps)
  std::function<PosePair(double tau)> motion;
  // m/s: no point of A approaches B faster than this over the search (zero: nothing approaches)
  double approachBound = 0.0;
  // s: the search covers τ in [0, horizon]
  double horizon = 0.0;
  // s: the time the search is part of (the rest of a step): the scale of the first look-ahead out
  // of a touching contact and of the narrowest root bracket
  double span = 0.0;
  // m: an impact is a gap within [0, tolerance]
  double tolerance = 0.0;
  // m: a pair this close at τ = 0 touches already (its impacts are answered); the search starts
  // where it gets clear of this band, or finds it coming back in before that
  double touching = 0.0;
};

// the first τ in [0, horizon] at which the shapes touch, or none. Never past the contact: the gap
// there is ≥ 0 (up to the round-off of the poses) and within the tolerance, or, when regula falsi
// ends the search, within a few tolerances (it stops when its kept gap, which the Illinois step
// halves, is within the tolerance)
std::optional<double> timeOfImpact(const ToiInput& input);

// the fastest any point of A can approach any point of B, m/s: |v_a − v_b| + |ω_a| R_a + |ω_b| R_b
// with R the largest distance of a shape's points from its body's center of mass
double approachBound(const sim::core::Shape& a, const sim::core::BodyState& sa, const sim::core::Shape& b,
                     const sim::core::BodyState& sb);

}  // namespace sim::collision

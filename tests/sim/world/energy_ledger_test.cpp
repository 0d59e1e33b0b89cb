// The energy ledger (energy_ledger.cpp): each account against its closed form, and the accounts
// adding up to the energy's change.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "sim/world/diagnostics.h"
#include "sim/world/energy_ledger.h"
#include "support/scene_text.h"

namespace {

using scene_text::build;

// E_end − E_start from the accounts
double balance(const sim::world::EnergyLedger& l) {
  return l.appliedWork + l.eventWork - l.lostAtImpacts - l.lostInContacts - l.lostToDamping - l.lostByIntegrator + l.gained;
}

}  // namespace

TEST_CASE("a ball dropped from h under event loses m g h (1 − c_r²) at its first impact, and nothing else") {
  // 1 kg from h = 1 m (its lowest point), c_r = 0.6: the motion between impacts is exact
  sim::world::World w = build(
      "world: {gravity: [0, -10], restitution: 0.6}\nsim: {collisions: event, dt: 0.01}\nbodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: ball, shape: {circle: 0.5}, mass: 1, position: [0, 1.5]}\n");
  sim::world::EnergyLedger ledger(w);
  // it lands at √(2h/g) = 0.447 s and rises again to 0.36 m by 0.447 + 2 × 0.6 × 0.447 s
  w.advanceTo(0.8, &ledger);
  REQUIRE(w.impacts.size() == 1);
  CHECK(ledger.lostAtImpacts == doctest::Approx(10.0 * (1.0 - 0.36)).epsilon(1e-12));
  CHECK(std::abs(ledger.lostByIntegrator) <= 1e-12);
  CHECK(ledger.gained <= 1e-12);
  CHECK(ledger.end - ledger.start == doctest::Approx(balance(ledger)).epsilon(1e-12));
}

TEST_CASE("drag's loss, a point force's work and an event's work, each against its closed form") {
  // a 2 kg disc, no gravity: a drag c = 0.5 from v₀ = 3 m/s loses ½ m v₀² (1 − e^(−2ct/m)) by t
  sim::world::World drag = build(
      "sim: {integrator: rk4, dt: 0.001}\nbodies: [{name: disc, shape: {circle: 0.5}, mass: 2, velocity: [3, 0]}]\n"
      "forces: [{type: drag, body: disc, linear: 0.5}]\n");
  sim::world::EnergyLedger dragged(drag);
  drag.advanceTo(2.0, &dragged);
  CHECK(dragged.lostToDamping == doctest::Approx(9.0 * (1.0 - std::exp(-1.0))).epsilon(1e-6));
  CHECK(dragged.end - dragged.start == doctest::Approx(balance(dragged)).epsilon(1e-12));

  // a constant force F = 4 N on 2 kg from rest for 1 s in 100 steps: it does F · Δx, and symplectic
  // Euler moves the puck h Σ vₖ = a h² N(N + 1)/2 = 1.01 m (a = 2 m/s²) while giving it the exact
  // v = F t/m, ½mv² = 4 J: the 0.04 J between is the integrator's; then an impulse event of 2 N·s
  // along it at t = 1 adds ½m((v + j/m)² − v²) = 5 J
  sim::world::World pushed = build(
      "sim: {dt: 0.01}\nbodies: [{name: puck, shape: {circle: 0.5}, mass: 2}]\n"
      "forces: [{type: force, body: puck, force: [4, 0]}]\nevents: [{time: 1, body: puck, impulse: [2, 0]}]\n");
  sim::world::EnergyLedger work(pushed);
  pushed.advanceTo(1.0, &work);
  CHECK(work.appliedWork == doctest::Approx(4.04).epsilon(1e-12));
  CHECK(work.lostByIntegrator == doctest::Approx(0.04).epsilon(1e-9));
  CHECK(work.eventWork == doctest::Approx(5.0).epsilon(1e-12));
  CHECK(work.gained <= 1e-12);
  CHECK(work.largestRise().amount <= 1e-12);
}

TEST_CASE("the accounts add up, and a gain says when and where") {
  // a damped spring, a drag, a point force and an impact under sequential
  sim::world::World w = build(
      "world: {gravity: [0, -9.81], friction: 0.3}\nsim: {collisions: sequential, integrator: midpoint, dt: 0.005}\nbodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: box, shape: {box: [1, 0.5]}, position: [0, 1], velocity: [1, -6], angular_velocity: 2}\n"
      "forces:\n  - {type: spring, body: box, point: [0.5, 0], anchor: [2, 3], stiffness: 1, rest_length: 1, damping: 0.5}\n"
      "  - {type: drag, body: box, linear: 0.1, angular: 0.05}\n  - {type: force, body: box, force: [1, 0], until: 1}\n"
      "events: [{time: 0.5, body: box, impulse: [0, 2], point: [0.3, 0]}]\n");
  sim::world::EnergyLedger ledger(w);
  w.advanceTo(3.0, &ledger);
  CHECK(ledger.end == doctest::Approx(sim::world::energy(w).total()).epsilon(1e-15));
  CHECK(ledger.end - ledger.start == doctest::Approx(balance(ledger)).epsilon(1e-12));
  CHECK(ledger.lostAtImpacts + ledger.lostInContacts > 0.0);
  CHECK(ledger.lostToDamping > 0.0);

  // explicit Euler on a free spring gains in free motion: the largest gain has no pair
  sim::world::World spring = build(
      "sim: {integrator: explicit_euler, dt: 0.01}\nbodies: [{name: mass, shape: {circle: 0.1}, mass: 1, position: [1, 0]}]\n"
      "forces: [{type: spring, body: mass, anchor: [0, 0], stiffness: 4}]\n");
  sim::world::EnergyLedger gains(spring);
  spring.advanceTo(1.0, &gains);
  CHECK(gains.gained == doctest::Approx(2.0 * (std::pow(1.0004, 100) - 1.0)).epsilon(1e-9));
  CHECK(gains.largestGain.a == -1);
  CHECK(gains.largestGain.time == doctest::Approx(1.0));
}

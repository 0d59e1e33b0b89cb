// `auto`'s watch over the event method (contact_watch.cpp): a contact that persists hands the run to
// the resting-contact solver at that step, so everyday scenes come out right at the defaults.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/world/diagnostics.h"
#include "sim/world/energy_ledger.h"
#include "support/scene_text.h"

namespace {

using namespace scene_text;

constexpr double kPi = 3.14159265358979323846;

// a w × h box of 1 kg tilted by `tilt`, spinning at `spin`, its center dropped from `height` onto a
// floor of restitution `cr` and friction `mu`; nothing else named: the defaults choose the method
std::string droppedBox(double w, double h, double tilt, double spin, double height, double cr, double mu) {
  return "duration: 5\nworld: {gravity: [0, -9.81], restitution: " + num(cr) + ", friction: " + num(mu) +
         "}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
         "  - {name: box, shape: {box: " +
         vec(w, h) + "}, mass: 1, position: " + vec(0, height) + ", angle: " + num(tilt) + ", angular_velocity: " + num(spin) +
         "}\n";
}

// the body's angle to the nearest quarter turn: how far it is from lying on a face
double offFace(double angle) { return std::abs(angle - 0.5 * kPi * std::round(angle / (0.5 * kPi))); }

}  // namespace

TEST_CASE("at the defaults, a tilted box dropped on a rough floor comes to rest on a face, its energy never rising") {
  struct Drop {
    double w, h, tilt, spin, height, cr, mu;
  };
  // the two (the 1 × 0.5 m box at 30°, c_r 0.5, μ 0.5; the crate at 20° spinning at 2 rad/s on
  // μ 0.6), and more tilts, restitutions and frictions
  for (const Drop d :
       {Drop{1, 0.5, kPi / 6, 0, 1.5, 0.5, 0.5}, Drop{1, 1, kPi / 9, 2, 1.3, 0.5, 0.6}, Drop{1, 0.5, kPi / 4, 0, 1.5, 0.8, 0.3},
        Drop{1, 0.5, 1.2, -1, 2.0, 0.2, 0.9}, Drop{2, 0.5, 0.1, 0, 1.0, 0.5, 0.5}, Drop{1, 0.5, kPi / 3, 0, 1.5, 0.0, 0.4}}) {
    CAPTURE(d.tilt);
    CAPTURE(d.cr);
    CAPTURE(d.mu);
    sim::world::World w = build(droppedBox(d.w, d.h, d.tilt, d.spin, d.height, d.cr, d.mu));
    w.start();
    CHECK(w.collisions() == sim::core::CollisionMethod::Event);
    sim::world::EnergyLedger ledger(w);
    w.advanceTo(5.0, &ledger);
    // handed over when contact persisted, well before the end, between the floor and the box
    CHECK(w.collisions() == sim::core::CollisionMethod::Sequential);
    CHECK(w.methodReason() == sim::core::MethodReason::ContactPersisted);
    REQUIRE(w.methodSwitch());
    CHECK(w.methodSwitch()->a == 0);
    CHECK(w.methodSwitch()->b == 1);
    CHECK(w.methodSwitch()->time < 2.0);
    // at rest, lying on a face: its center one half-side above the floor
    const sim::core::Body& box = w.bodies[1];
    CHECK(box.v.norm() <= 1e-9);
    CHECK(std::abs(box.omega) <= 1e-9);
    const bool upright = std::abs(std::cos(box.angle)) > 0.5;
    // (its two lower corners within the slop of the floor)
    CHECK(offFace(box.angle) * (upright ? d.w : d.h) <= sim::core::settings::kLinearSlop);
    CHECK(std::abs(box.x.y() - 0.5 * (upright ? d.h : d.w)) <= sim::core::settings::kLinearSlop);
    // the energy never rose above its lowest so far by more than a micro-joule (the position pass
    // settles within the slop)
    CHECK(ledger.largestRise().amount <= 1e-6);
    CHECK(ledger.end < ledger.start);
  }
}

TEST_CASE("the watch: slow impacts repeated within the window hand over, fast and isolated ones stay with event") {
  // a ball on a floor rattles: c_r = 0.5 from 2 cm (beyond the contact margin: apart at the start),
  // its bounces shrinking under 25 ms apart
  sim::world::World rattle = build(
      "world: {gravity: [0, -9.81], restitution: 0.5}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, "
      "1]}}}\n  - {name: ball, shape: {circle: 0.1}, position: [0, 0.12]}\n");
  rattle.advanceTo(1.0);
  REQUIRE(rattle.methodSwitch());
  CHECK(rattle.methodSwitch()->how == sim::core::Persistence::Rattling);
  // its switch comes at the end of the step of the impact that made four within the window, on the
  // step grid, and no three impacts before it were within a window
  std::vector<double> times;
  for (const sim::world::ImpactRecord& r : rattle.impacts)
    if (r.t <= rattle.methodSwitch()->time) times.push_back(r.t);
  REQUIRE(times.size() >= 4);
  const double last = times.back();
  CHECK(rattle.methodSwitch()->time == doctest::Approx(std::ceil(last / rattle.def().dt) * rattle.def().dt).epsilon(1e-12));
  CHECK(last - times[times.size() - 4] <= sim::core::settings::kRepeatWindow);
  for (size_t k = 3; k + 1 < times.size(); ++k) CHECK(times[k] - times[k - 3] > sim::core::settings::kRepeatWindow);
  CHECK(rattle.bodies[1].v.norm() <= 1e-9);

  // Newton's cradle: the balls touch from the start and strike each other, but no force presses them
  // together and their impacts are fast: it stays with event, whose closed forms it keeps
  const scene_text::CradleRun cradle = scene_text::runCradle(sim::core::CollisionMethod::Auto);
  CHECK(cradle.world.collisions() == sim::core::CollisionMethod::Event);
  CHECK_FALSE(cradle.world.methodSwitch());

  // a ball thrown along a floor at 5 m/s bounces from 1 m at c_r 0.9: isolated impacts, far apart
  sim::world::World bounce = build(
      "world: {gravity: [0, -9.81], restitution: 0.9}\nbodies:\n  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, "
      "1]}}}\n  - {name: ball, shape: {circle: 0.1}, position: [0, 1], velocity: [5, 0]}\n");
  bounce.advanceTo(2.0);
  CHECK_FALSE(bounce.methodSwitch());
  CHECK(bounce.impacts.size() >= 2);
}

// What stays on screen after it happens: contacts held and fading after a touch ends, an event's
// impulse arrow ending at the point it strikes, trails with nearby points merged.
#include <doctest/doctest.h>

#include <string>

#include "render/frame/history.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"

using render::draw::DrawList;
using render::draw::Role;
using render::frame::History;

namespace {

// a ball moving right at 1 m/s, and a kick at t = 0.5
sim::world::World ballWorld() {
  return sim::scene::buildWorld(
      sim::yaml::loadSceneText("duration: 2\n"
                               "bodies:\n"
                               "  - {name: ball, shape: {circle: 0.5}, velocity: [1, 0]}\n"
                               "events:\n"
                               "  - {time: 0.5, body: ball, impulse: [0, 2], point: [0, 0]}\n",
                               "inline.yaml"));
}

// a made-up contact while the ball's center is in [0.2, 0.4] (with room for round-off), its normal up
void fakeContacts(const sim::world::World& w, std::vector<sim::describe::ContactMark>& marks) {
  const double x = w.bodies[0].x.x();
  if (x >= 0.1995 && x <= 0.4005) marks.push_back({{x, 0}, {0, 1}});
}

// options with the afterimages and trails asked for, the rest off
History::Options options(bool trails, double hold, bool events, bool impacts, History::ContactSource contacts = {}) {
  History::Options o;
  o.trails = trails, o.hold = hold, o.eventImpulses = events, o.impacts = impacts, o.contacts = std::move(contacts);
  return o;
}

// arrows `impulseScale` m per N·s, normals `normalLength` m
History::Look look(double impulseScale = 1.0, double normalLength = 1.0) { return {impulseScale, normalLength, std::nullopt}; }

// what the history shows at the world's time, as draw-list text
std::string afterimages(const History& h, const sim::world::World& w, const History::Look& l = look()) {
  DrawList d;
  h.drawAfterimages(w, l, d);
  return d.toText();
}

}  // namespace

TEST_CASE("a contact stays after the touch ends, fading linearly over the hold time") {
  sim::world::World w = ballWorld();
  History h(w, options(false, 0.5, false, false, fakeContacts));
  w.advanceTo(0.3, &h);
  // touching: the latest contact, fully opaque, only once, its normal as long as the look says
  CHECK(afterimages(h, w, look(1.0, 0.25)) == "arrow ContactNormal (0.3,0) -> (0.3,0.25)\npoint ContactPoint (0.3,0)\n");
  w.advanceTo(0.65, &h);  // the touch ended at 0.4: 0.25 s ago, half the hold
  CHECK(afterimages(h, w) == "arrow ContactNormal@0.5 (0.4,0) -> (0.4,1)\npoint ContactPoint@0.5 (0.4,0)\n");
  w.advanceTo(0.95, &h);
  CHECK(afterimages(h, w).empty());
}

TEST_CASE("a second touch is a moment of its own, kept up to date, while the first one fades") {
  // touching while the ball's center is in [0.2, 0.4] and again in [0.6, 0.7]
  const auto twice = [](const sim::world::World& w, std::vector<sim::describe::ContactMark>& marks) {
    const double x = w.bodies[0].x.x();
    if ((x >= 0.1995 && x <= 0.4005) || (x >= 0.5995 && x <= 0.7005)) marks.push_back({{x, 0}, {0, 1}});
  };
  sim::world::World w = ballWorld();
  History h(w, options(false, 0.5, false, false, twice));
  // the points alone, the normals filtered out
  const auto points = [&] {
    DrawList all, kept;
    h.drawAfterimages(w, look(), all);
    render::draw::RoleFilter filter(kept, [](Role r) { return r == Role::ContactPoint; });
    all.replay(filter);
    return kept.toText();
  };
  w.advanceTo(0.65, &h);
  CHECK(points() == "point ContactPoint@0.5 (0.4,0)\npoint ContactPoint (0.65,0)\n");
  w.advanceTo(0.8, &h);
  CHECK(points() == "point ContactPoint@0.2 (0.4,0)\npoint ContactPoint@0.8 (0.7,0)\n");
}

TEST_CASE("an event's impulse is an arrow ending where it strikes, scaled, held like a contact") {
  sim::world::World w = ballWorld();
  History h(w, options(false, 0.5, true, false));
  w.advanceTo(0.5, &h);
  CHECK(afterimages(h, w, look(0.25)) == "arrow Impulse#0 (0.5,-0.5) -> (0.5,0)\n");
  // the arrow stays where the blow fell while the body moves on, and scales with the look
  w.advanceTo(0.75, &h);
  CHECK(afterimages(h, w, look(0.5)) == "arrow Impulse#0@0.5 (0.5,-1) -> (0.5,0)\n");
  w.advanceTo(1.2, &h);
  CHECK(afterimages(h, w, look(0.25)).empty());
}

TEST_CASE("trails follow the center of mass, points closer than the spacing merged") {
  sim::world::World w = ballWorld();
  History h(w, options(true, 0.5, false, false));
  w.advanceTo(0.4, &h);
  DrawList fine, coarse;
  // spacings a little under 10 and 150 steps of 1 mm, so that round-off does not skip a point
  h.drawTrails(fine, 0.0095);
  h.drawTrails(coarse, 0.1495);
  CHECK(fine.calls().size() == 40);
  // 0.15 m apart at 1 m/s: a segment per 0.15 s, and one to the present position
  CHECK(coarse.toText() == "segment Trail#0 (0,0) (0.15,0)\nsegment Trail#0 (0.15,0) (0.3,0)\nsegment Trail#0 (0.3,0) (0.4,0)\n");
}

TEST_CASE("a trail kept at its drawing spacing draws as the trail of every step, from far fewer points") {
  History::Options every = options(true, 0.5, false, false);
  History::Options spaced = every;
  spaced.trailSpacing = 0.1495;
  sim::world::World a = ballWorld(), b = ballWorld();
  History all(a, every), kept(b, spaced);
  // through the kick at t = 0.5: the path turns, and the points kept must turn with it
  a.advanceTo(1.2, &all);
  b.advanceTo(1.2, &kept);
  DrawList fromAll, fromKept;
  all.drawTrails(fromAll, 0.1495);
  kept.drawTrails(fromKept, 0.1495);
  CHECK(fromKept.toText() == fromAll.toText());
  CHECK(fromAll.calls().size() > 3);
  // and a trail drawn finer than it was kept shows only what was kept: a segment per 0.15 m
  DrawList fine;
  kept.drawTrails(fine, 0.0095);
  CHECK(fine.calls().size() == fromKept.calls().size());
}

TEST_CASE("an impact shows its point, its normal and the impulse on the moving body, then fades") {
  // a ball (A, body 0) at 1 m/s meets a static wall (B) whose face is at x = 1.5 at t = 1
  sim::world::World w =
      sim::scene::buildWorld(sim::yaml::loadSceneText("duration: 2\n"
                                                      "world: {restitution: 1}\n"
                                                      "sim: {collisions: event}\n"
                                                      "bodies:\n"
                                                      "  - {name: ball, shape: {circle: 0.5}, mass: 2, velocity: [1, 0]}\n"
                                                      "  - {name: wall, shape: {box: [1, 4]}, position: [2, 0], static: true}\n",
                                                      "inline.yaml"));
  History h(w, options(false, 0.5, false, true));
  w.advanceTo(1.1, &h);
  // γ = (1 + c_r) m |v_n| = 4 N·s, 1 m of arrow at 0.25 m per N·s, on the ball only (the wall
  // does not move); n̂ from the wall (B) into the ball (A)
  CHECK(afterimages(h, w, look(0.25, 1.0)) ==
        "arrow Impulse#0@0.8 (1.5,0) -> (0.5,0)\n"
        "arrow ContactNormal@0.8 (1.5,0) -> (0.5,0)\n"
        "point ContactPoint@0.8 (1.5,0)\n");
  // the same impact drawn at other scales: the history keeps what happened, the look how it shows
  CHECK(afterimages(h, w, look(0.5, 0.25)) ==
        "arrow Impulse#0@0.8 (1.5,0) -> (-0.5,0)\n"
        "arrow ContactNormal@0.8 (1.5,0) -> (1.25,0)\n"
        "point ContactPoint@0.8 (1.5,0)\n");
  w.advanceTo(1.6, &h);
  CHECK(afterimages(h, w, look(0.25, 1.0)).empty());
}

TEST_CASE("a pair that hits again replaces its last impact instead of piling up arrows") {
  // a ball bouncing on a floor (A, static: the normal turns to point into the ball)
  sim::world::World w =
      sim::scene::buildWorld(sim::yaml::loadSceneText("duration: 3\n"
                                                      "world: {gravity: [0, -10], restitution: 0.5}\n"
                                                      "sim: {collisions: event}\n"
                                                      "bodies:\n"
                                                      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
                                                      "  - {name: ball, shape: {circle: 0.1}, position: [0, 0.3]}\n",
                                                      "inline.yaml"));
  History h(w, options(false, 2.0, false, true));
  // the bounces pile up by t = 0.2 · 1.5 / 0.5 = 0.6 s
  w.advanceTo(1.0, &h);
  REQUIRE(w.impacts.size() > 3);
  DrawList shown;
  h.drawAfterimages(w, look(0.0, 0.5), shown);
  const auto lines = shown.lines();
  // one impact's normal and point (no impulse on the floor; a zero scale for the ball's)
  REQUIRE(lines.size() == 3);
  CHECK(lines[1].find("arrow ContactNormal") == 0);
  CHECK(lines[1].find("-> (0,0.5)") != std::string::npos);
}

TEST_CASE("a history of every step respaced keeps what a history kept at that spacing keeps, then and after") {
  History::Options every = options(true, 0.5, false, false);
  History::Options spaced = every;
  spaced.trailSpacing = 0.1495;
  sim::world::World a = ballWorld(), b = ballWorld();
  History all(a, every), kept(b, spaced);
  // the trail points each holds, every one drawn (spacing 0)
  const auto points = [](const History& h) {
    DrawList d;
    h.drawTrails(d, 0.0);
    return d.toText();
  };
  a.advanceTo(0.62, &all);
  b.advanceTo(0.62, &kept);
  REQUIRE(points(all) != points(kept));
  all.respace(0.1495);
  CHECK(points(all) == points(kept));
  CHECK(all.pathBytes() < 10 * sizeof(sim::core::Vec2) + kept.pathBytes());
  // and it goes on as the spaced one does: through the kick, the latest point replacing one not kept
  a.advanceTo(1.2, &all);
  b.advanceTo(1.2, &kept);
  CHECK(points(all) == points(kept));
}

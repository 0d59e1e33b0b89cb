// The teaching arrows as draw calls: the notes' vectors at a body point, exact, with their labels.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "render/frame/quantity_text.h"
#include "render/frame/teaching_arrows.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"

using render::draw::DrawList;
using render::draw::Role;
using sim::core::Vec2;

namespace {

// a bar turned by 0.5 rad, moving and spinning, pushed up at its top; a 10 m high view, 200×100 px
const std::string kScene = R"(
duration: 1
bodies:
  - {name: bar, shape: {box: [0.2, 2]}, mass: 2, inertia: 1, angle: 0.5, velocity: [1, 0.5], angular_velocity: 2}
  - {name: tri, shape: {polygon: [[0, 0], [3, 0], [0, 3]]}, position: [5, 0], angle: 0.5}
forces:
  - {type: force, body: bar, point: [0, 1], force: [0, 3]}
render:
  size: [200, 100]
  camera: {center: [0, 0], height: 10}
  velocity_scale: 1
  force_scale: 0.5
  momentum_scale: 0.25
  arrows:
)";

struct Drawn {
  render::scene::Scene def;
  render::frame::RunSurvey survey;
  sim::world::World world;
  DrawList list;
};

// the arrows of `entries` at time t
Drawn arrowsAt(const std::string& entries, double t = 0.0) {
  Drawn d{drawn_scene::load(kScene + entries), {}, {}, {}};
  d.survey = render::frame::surveyRun(d.def);
  const render::draw::Camera camera = render::frame::cameraFor(d.def, d.survey);
  const render::frame::TeachingArrows arrows(d.def, camera, d.survey, 1.0);
  d.world = sim::scene::buildWorld(d.def.model);
  render::frame::History::Options o;
  o.points = render::frame::TeachingArrows::pathsOf(d.def);
  render::frame::History history(d.world, o);
  d.world.advanceTo(t, &history);
  arrows.draw(d.world, history, d.list);
  return d;
}

void checkPoint(const Vec2& got, const Vec2& want) {
  CHECK(got.x() == doctest::Approx(want.x()).epsilon(1e-12));
  CHECK(got.y() == doctest::Approx(want.y()).epsilon(1e-12));
}

const Vec2 kTop(-std::sin(0.5), std::cos(0.5));  // R r_b of the bar's top, r_b = (0, 1)

}  // namespace

TEST_CASE("velocity at a body point is v + ω × R r_b, labeled with its magnitude") {
  const Drawn d = arrowsAt("    - {body: bar, show: velocity, at: [0, 1], value: true}\n");
  REQUIRE(d.list.calls().size() == 2);
  const auto& arrow = d.list.calls()[0];
  CHECK(arrow.kind == DrawList::Kind::Arrow);
  CHECK(arrow.style.role == Role::Velocity);
  const Vec2 v = Vec2(1, 0.5) + 2.0 * Vec2(-kTop.y(), kTop.x());
  checkPoint(arrow.points[0], kTop);
  checkPoint(arrow.points[1], kTop + v);
  CHECK(d.list.calls()[1].text == render::frame::quantityText("v", v.norm(), "m/s"));
  CHECK(d.list.calls()[1].style.role == Role::Label);
}

TEST_CASE("offset r′ = R r_b from the center of mass, `at` as written before the centroid shift") {
  const Drawn d = arrowsAt(
      "    - {body: bar, show: offset, at: [0, 1]}\n"
      "    - {body: tri, show: offset, at: [0, 0], label: corner}\n");
  REQUIRE(d.list.calls().size() == 4);
  checkPoint(d.list.calls()[0].points[0], Vec2::Zero());
  checkPoint(d.list.calls()[0].points[1], kTop);
  CHECK(d.list.toText().find("\"r′\"") != std::string::npos);
  // the triangle's centroid is (1, 1) as written: its corner (0, 0) lies at R (−1, −1) from x
  const sim::core::Rot q = sim::core::Rot::fromAngle(0.5);
  checkPoint(d.list.calls()[2].points[1], Vec2(5, 0) + q.apply(Vec2(-1, -1)));
  CHECK(d.list.calls()[3].text == "corner");
}

TEST_CASE("force at its point, momentum from the center, each by its scale") {
  const Drawn d = arrowsAt(
      "    - {body: bar, show: force, value: true}\n"
      "    - {body: bar, show: momentum, color: '#ff0000'}\n");
  REQUIRE(d.list.calls().size() == 4);
  checkPoint(d.list.calls()[0].points[0], kTop);
  checkPoint(d.list.calls()[0].points[1], kTop + 0.5 * Vec2(0, 3));
  CHECK(d.list.calls()[1].text == "f = 3.00 N");
  checkPoint(d.list.calls()[2].points[1], 0.25 * 2.0 * Vec2(1, 0.5));
  // its own color: teaching arrow 1
  CHECK(d.list.lines()[2].rfind("arrow Momentum#0~1 ", 0) == 0);
}

TEST_CASE("ω is a counter-clockwise arc over the top for ω > 0, its sweep |ω| / the run's largest × 270°") {
  const Drawn d = arrowsAt("    - {body: bar, show: omega, value: true}\n");
  const auto& calls = d.list.calls();
  REQUIRE(calls.size() >= 3);
  const double sweep = 1.5 * std::numbers::pi * 2.0 / d.survey.maxOmega;
  const double from = 0.5 * std::numbers::pi - 0.5 * sweep, to = 0.5 * std::numbers::pi + 0.5 * sweep;
  // radius 0.06 of the 10 m view
  checkPoint(calls.front().points[0], 0.6 * Vec2(std::cos(from), std::sin(from)));
  const auto& head = calls[calls.size() - 2];
  CHECK(head.kind == DrawList::Kind::Arrow);
  checkPoint(head.points[1], 0.6 * Vec2(std::cos(to), std::sin(to)));
  CHECK(calls.back().text == "ω = 2.00 rad/s");
}

TEST_CASE("τ = r′ × f of the point forces, clockwise under the bottom when negative") {
  const Drawn d = arrowsAt("    - {body: bar, show: torque, value: true}\n");
  const double tau = sim::core::cross(kTop, Vec2(0, 3));
  CHECK(d.list.calls().back().text == "τ = " + render::frame::signedNumber(tau) + " N·m");
  CHECK(d.list.calls().back().text.find("−") != std::string::npos);
  const auto& head = d.list.calls()[d.list.calls().size() - 2];
  const double to = -0.5 * std::numbers::pi + 0.5 * 1.5 * std::numbers::pi * tau / d.survey.maxTorque;
  checkPoint(head.points[1], 0.9 * Vec2(std::cos(to), std::sin(to)));
}

TEST_CASE("the body frame's axes R x̂ and R ŷ, labeled x_b and y_b") {
  const Drawn d = arrowsAt("    - {body: bar, show: frame}\n");
  REQUIRE(d.list.calls().size() == 4);
  checkPoint(d.list.calls()[0].points[1], Vec2(std::cos(0.5), std::sin(0.5)));
  checkPoint(d.list.calls()[1].points[1], kTop);
  CHECK(d.list.calls()[2].text == "x_b");
  CHECK(d.list.calls()[3].text == "y_b");
}

TEST_CASE("the path of a body point ends at the point now, with a dot there") {
  const Drawn d = arrowsAt("    - {body: bar, show: path, at: [0, 1]}\n", 0.5);
  const auto& calls = d.list.calls();
  REQUIRE(calls.size() >= 3);
  const sim::core::Body& b = d.world.bodies[0];
  const Vec2 now = b.pose().toWorld(Vec2(0, 1));
  checkPoint(calls[0].points[0], kTop);
  checkPoint(calls[calls.size() - 3].points[1], now);
  CHECK(calls[calls.size() - 2].kind == DrawList::Kind::Point);
  checkPoint(calls[calls.size() - 2].points[0], now);
  CHECK(calls.back().text == "r");
}

TEST_CASE("an arrow of no length is a dot with its label: the rolling contact's v = 0") {
  // the point of the bar whose velocity is zero now: v + ω × r′ = 0 at r′ = ẑ × v / ω = (−0.25, 0.5)
  // in the world, i.e. R(−0.5) of it in the bar's coordinates
  const Vec2 r = sim::core::Rot::fromAngle(-0.5).apply(Vec2(-0.25, 0.5));
  char at[96];
  std::snprintf(at, sizeof at, "[%.17g, %.17g]", r.x(), r.y());
  const Drawn d = arrowsAt("    - {body: bar, show: velocity, at: " + std::string(at) + ", value: true}\n");
  REQUIRE(d.list.calls().size() == 2);
  CHECK(d.list.calls()[0].kind == DrawList::Kind::Point);
  CHECK(d.list.calls()[0].style.role == Role::Velocity);
  CHECK(d.list.calls()[1].kind == DrawList::Kind::Label);
  CHECK(d.list.calls()[1].text == "v = 0 m/s");
  // labelled out from the center of mass, away from the body
  const Vec2 out = d.list.calls()[1].points[1];
  CHECK(out.dot(Vec2(-0.25, 0.5).normalized()) == doctest::Approx(1.0).epsilon(1e-5));
}

// A poll's impulses still to come (upcoming_events.cpp): dashed arrows ending where they will strike,
// labelled with their time, drawn only before they act and only in a scene that asks a question; so
// that a question sheet of variants struck at the center or at the end shows the difference at t = 0.
#include "render/frame/upcoming_events.h"

#include <doctest/doctest.h>

#include "render/frame/scene_run.h"
#include "support/drawn_scene.h"
#include "support/redefined.h"

using render::draw::DrawList;
using render::draw::Role;
using sim::core::Vec2;

namespace {

// the notes' poll: a bar at rest struck by j = (1, 0) at its end (0, 2) at t = 0.5
const std::string kPoll = R"(
duration: 1
question: Which one turns?
bodies:
  - {name: bar, shape: {box: [0.2, 4]}, mass: 3, inertia: 4}
events:
  - {time: 0.5, body: bar, impulse: [1, 0], point: [0, 2]}
render: {size: [640, 360]}
)";

DrawList frameAt(const std::string& yaml, double t) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  return run.drawListAt(t);
}

}  // namespace

TEST_CASE("an impulse still to come: a dashed shaft, a solid head at its point, its time beside the tail") {
  sim::world::World world;
  world.bodies.resize(1);
  world.bodies[0].x = Vec2(1, 0);
  world = fixtures::redefined(world, [&](auto& d) { d.events.push_back({0.5, 0, Vec2(0, 2), false, Vec2(1, 0)}); });
  const render::draw::Camera camera(Vec2::Zero(), 10.0, 640, 360);
  DrawList list;
  // 2 m of arrow: the shaft from (−1, 2) to the neck 24 px short of the point (1, 2)
  render::frame::drawUpcomingEvents(world, 2.0, camera, 2.0, list);
  int dashes = 0;
  const DrawList::Call* head = nullptr;
  const DrawList::Call* label = nullptr;
  for (const DrawList::Call& c : list.calls()) {
    if (c.kind == DrawList::Kind::Segment && c.style.role == Role::Impulse) ++dashes;
    if (c.kind == DrawList::Kind::Arrow) head = &c;
    if (c.kind == DrawList::Kind::Label) label = &c;
  }
  // 2 m at 36 px/m less the head, in dashes of 8 px with 6 px gaps: several, apart
  CHECK(dashes >= 3);
  REQUIRE(head);
  CHECK(head->points[1].x() == doctest::Approx(1.0));
  CHECK(head->points[1].y() == doctest::Approx(2.0));
  CHECK((head->points[1] - head->points[0]).norm() == doctest::Approx(24 * camera.pixelSize()));
  REQUIRE(label);
  CHECK(label->text == "j at t = 0.5 s");
  CHECK(label->points[0].x() == doctest::Approx(-1.0));
  // once it has struck (a frame at its time shows the state after it), nothing
  world.time = 0.5;
  DrawList after;
  render::frame::drawUpcomingEvents(world, 2.0, camera, 2.0, after);
  CHECK(after.empty());
}

TEST_CASE("a poll's question frame shows its impulses to come; a scene without a question does not") {
  const std::string question = frameAt(kPoll, 0.0).toText();
  CHECK(question.find("\"j at t = 0.5 s\"") != std::string::npos);
  CHECK(question.find("segment Impulse#0") != std::string::npos);
  // after the impulse the frame shows it struck, not to come
  CHECK(frameAt(kPoll, 0.75).toText().find("j at t") == std::string::npos);
  std::string plain = kPoll;
  plain.erase(plain.find("question:"), std::string("question: Which one turns?\n").size());
  CHECK(frameAt(plain, 0.0).toText().find("j at t") == std::string::npos);
}

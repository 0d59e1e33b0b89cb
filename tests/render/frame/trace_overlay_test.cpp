// Another trajectory over ours (--overlay): the frame with it is the frame without it plus the
// dashed outlines and the legend, call for call, and pixel for pixel outside where those are drawn.
#include <doctest/doctest.h>

#include <cmath>

#include "render/draw/gl_context.h"
#include "render/draw/text.h"
#include "render/frame/scene_run.h"
#include "render/frame/survey.h"
#include "support/drawn_scene.h"

using namespace render::draw;
using render::frame::SceneRun;
using sim::core::Vec2;

namespace {

// a ball and a box; the other run has each 0.6 m higher and the box turned 0.5 rad more
const std::string kScene = R"(
name: pair
duration: 1
bodies:
  - {name: ball, shape: {circle: 0.25}, position: [0, 0], velocity: [1, 0], label: ball}
  - {name: box, shape: {box: [0.5, 0.5]}, position: [2, 0], angular_velocity: 1, label: box}
render: {size: [320, 180]}
)";

render::scene::Scene withOverlay(render::scene::Scene scene) {
  auto overlay = std::make_shared<render::scene::TraceOverlayDef>();
  overlay->name = "theirs.csv";
  overlay->poseAt = [](size_t body, double t, render::scene::TraceOverlayDef::Pose& pose) {
    pose =
        body == 0 ? render::scene::TraceOverlayDef::Pose{{t, 0.6}, 0.0} : render::scene::TraceOverlayDef::Pose{{2, 0.6}, t + 0.5};
    return true;
  };
  scene.render.overlay = overlay;
  return scene;
}

bool legendText(const DrawList::Call& c) {
  return c.kind == DrawList::Kind::Text && (c.text == "rigidreel" || c.text == "theirs.csv");
}

// the distance from p to the segment ab
double distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double f = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (a + f * d)).norm();
}

}  // namespace

TEST_CASE("with --overlay, a frame's calls are its calls without, plus dashed outlines and the legend") {
  const render::scene::Scene plain = drawn_scene::load(kScene);
  const render::scene::Scene over = withOverlay(plain);
  const render::frame::RunSurvey survey = render::frame::surveyRun(plain);
  const Camera camera = render::frame::cameraFor(plain, survey);
  TextRenderer text;
  GlContext gl(320, 180);
  SceneRun a(plain, camera, survey), b(over, camera, survey);
  const DrawList without = a.drawListAt(0.5), with = b.drawListAt(0.5);
  // the calls of `with` that are not the overlay's, in order, are exactly `without`'s
  std::vector<std::string> lines = with.lines(), kept;
  size_t dashes = 0, legend = 0;
  for (size_t i = 0; i < with.calls().size(); ++i) {
    const DrawList::Call& c = with.calls()[i];
    if (c.style.role == Role::Overlay) ++dashes;
    else if (legendText(c) || (c.kind == DrawList::Kind::Segment && c.style.role == Role::Caption)) ++legend;
    else kept.push_back(lines[i]);
  }
  CHECK(kept == without.lines());
  CHECK(legend == 3);  // the solid sample and the two names
  CHECK(dashes > 20);  // dashed: many segments around each outline
  // every dash lies on their outline: the ball's circle (radius 0.25 around (0.5, 0.6)) or radius,
  // or the box's edges, half-width 0.25 around (2, 0.6) turned by 1 rad; the legend's in the corner
  const Vec2 ball(0.5, 0.6), box(2, 0.6);
  const sim::core::Rot turn = sim::core::Rot::fromAngle(1.0);
  for (const DrawList::Call& c : with.calls()) {
    if (c.style.role != Role::Overlay || c.kind != DrawList::Kind::Segment) continue;
    for (const Vec2& p : c.points) {
      const Vec2 local = turn.applyInverse(p - box);
      const bool onBall = std::abs((p - ball).norm() - 0.25) < 1e-3 || (std::abs(p.y() - 0.6) < 1e-9 && p.x() >= 0.5 - 1e-9);
      const bool onBox = std::abs(std::max(std::abs(local.x()), std::abs(local.y())) - 0.25) < 1e-9;
      const Vec2 pixel = camera.toPixel(p);
      const bool inLegend = pixel.x() < 60 && pixel.y() < 80;
      CHECK_MESSAGE((onBall || onBox || inLegend), "a dash at (" << p.x() << ", " << p.y() << ")");
    }
  }
  // the pixels: the frames differ only within 3 px of a dash or in the legend's box
  SceneRun pa(plain, camera, survey, &gl, &text), pb(over, camera, survey, &gl, &text);
  const Image fa = pa.frameAt(0.5), fb = pb.frameAt(0.5);
  long differing = 0, stray = 0;
  for (int y = 0; y < fa.height; ++y)
    for (int x = 0; x < fa.width; ++x) {
      bool same = true;
      for (int k = 0; k < 3; ++k) same = same && fa.pixel(x, y)[k] == fb.pixel(x, y)[k];
      if (same) continue;
      ++differing;
      const Vec2 at(x + 0.5, y + 0.5);
      bool near = at.x() < 90 && at.y() < 80;
      for (const DrawList::Call& c : with.calls())
        if (!near && c.style.role == Role::Overlay && c.kind == DrawList::Kind::Segment)
          near = distance(at, camera.toPixel(c.points[0]), camera.toPixel(c.points[1])) <= 3.0;
      stray += !near;
    }
  CHECK(differing > 100);
  CHECK(stray == 0);
}

namespace {

// the other run's ball flies up to 6.9 m while ours rolls along the floor
render::scene::Scene flyingAway(render::scene::Scene scene) {
  auto overlay = std::make_shared<render::scene::TraceOverlayDef>();
  overlay->name = "student.csv";
  overlay->poseAt = [](size_t body, double t, render::scene::TraceOverlayDef::Pose& pose) {
    pose = body == 0 ? render::scene::TraceOverlayDef::Pose{{t, 6.9 * t}, 0.0} : render::scene::TraceOverlayDef::Pose{{2, 0}, t};
    return true;
  };
  scene.render.overlay = overlay;
  return scene;
}

}  // namespace

TEST_CASE("--overlay: the automatic camera fits both runs, theirs flying off as ours rolls on") {
  const render::scene::Scene over = flyingAway(drawn_scene::load(kScene));
  const render::frame::RunSurvey survey = render::frame::surveyRun(over);
  const Camera camera = render::frame::cameraFor(over, survey);
  const render::draw::Bounds view = camera.view();
  for (double t : {0.0, 0.5, 1.0}) {
    CAPTURE(t);
    // their ball (radius 0.25) and ours, whole, inside the frame
    for (const Vec2& c : {Vec2(t, 6.9 * t), Vec2(t, 0.0)}) {
      CHECK(c.x() - 0.25 >= view.min.x());
      CHECK(c.x() + 0.25 <= view.max.x());
      CHECK(c.y() - 0.25 >= view.min.y());
      CHECK(c.y() + 0.25 <= view.max.y());
    }
  }
  // without the overlay, the camera fits ours alone: theirs at t = 1 would be out of it
  const render::scene::Scene plain = drawn_scene::load(kScene);
  CHECK(render::frame::cameraFor(plain, render::frame::surveyRun(plain)).view().max.y() < 6.9);
}

TEST_CASE("--overlay: a body of theirs out of a fixed camera's frame has an arrow at the edge pointing to it") {
  std::string fixed = kScene;
  fixed.replace(fixed.find("render: {size: [320, 180]}"), 26, "render: {size: [320, 180], camera: {center: [1, 0], height: 3}}");
  const render::scene::Scene over = flyingAway(drawn_scene::load(fixed));
  const render::frame::RunSurvey survey = render::frame::surveyRun(over);
  const Camera camera = render::frame::cameraFor(over, survey);
  SceneRun run(over, camera, survey);
  const DrawList at1 = run.drawListAt(1.0);
  const DrawList::Call* edge = nullptr;
  for (const DrawList::Call& c : at1.calls())
    if (c.kind == DrawList::Kind::Arrow && c.style.role == Role::Overlay) edge = &c;
  REQUIRE(edge);
  // at the top edge, pointing up toward (1, 6.9)
  const Vec2 head = camera.toPixel(edge->points[1]), tail = camera.toPixel(edge->points[0]);
  CHECK(head.y() < tail.y());
  CHECK(head.y() > 0.0);
  CHECK(head.y() < 40.0);
  // in the frame at t = 0 both are in it: no arrow
  SceneRun fresh(over, camera, survey);
  // (the list kept: a range-for over a temporary's calls() would read it after its end)
  const DrawList at0 = fresh.drawListAt(0.0);
  for (const DrawList::Call& c : at0.calls()) CHECK_FALSE((c.kind == DrawList::Kind::Arrow && c.style.role == Role::Overlay));
}

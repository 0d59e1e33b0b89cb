// The panels' camera (panel_camera.cpp): grown until every arrow and body each panel draws at its
// instant lies inside its frame, where a camera fitted over the bodies alone clips a fast body's
// velocity arrow at the border.
#include <doctest/doctest.h>

#include "render/frame/panel_camera.h"
#include "render/frame/scene_run.h"
#include "support/drawn_scene.h"

namespace {

bool inside(const render::draw::Bounds& outer, const render::draw::Bounds& inner) {
  return outer.min.x() <= inner.min.x() && outer.min.y() <= inner.min.y() && inner.max.x() <= outer.max.x() &&
         inner.max.y() <= outer.max.y();
}

}  // namespace

TEST_CASE("drawn bounds: shapes and arrows count; texts, labels and the energy panel do not") {
  render::draw::DrawList list;
  list.arrow({0, 0}, {5, 1}, {render::draw::Role::Velocity, 0, 1.0});
  list.circle({-1, 0}, 0.5, {render::draw::Role::Body, 0, 1.0});
  list.text({100, 100}, "t = 0.000 s", {render::draw::Role::Caption, -1, 1.0});
  list.label({50, 50}, {0, 0}, "ball", {render::draw::Role::Label, 0, 1.0});
  list.polygon({{90, 90}, {91, 90}, {91, 91}}, {render::draw::Role::Panel, -1, 1.0});
  const render::draw::Bounds b = render::frame::drawnBounds(list);
  CHECK(b.min == sim::core::Vec2(-1.5, -0.5));
  CHECK(b.max == sim::core::Vec2(5, 1));
}

TEST_CASE("a panel camera holds every arrow each panel draws, where the bodies' camera does not") {
  // a ball at 1 m/s drawn at 5 m per m/s: at t = 0 its velocity arrow reaches far past the run's bounds
  const std::string yaml = drawn_scene::bounce("0.3", "render: {velocities: true, size: [640, 360], velocity_scale: 5}\n");
  const render::scene::Scene s = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(s);
  const render::draw::Camera plain = render::frame::cameraFor(s, survey);
  const auto arrowsAt = [&](const render::draw::Camera& camera) {
    render::frame::SceneRun run(s, camera, survey);
    render::draw::Bounds arrows;
    const render::draw::DrawList list = run.drawListAt(0.0);
    for (const auto& c : list.calls())
      if (c.kind == render::draw::DrawList::Kind::Arrow)
        for (const auto& p : c.points) arrows.add(p);
    return arrows;
  };
  REQUIRE_FALSE(arrowsAt(plain).empty());
  CHECK_FALSE(inside(plain.view(), arrowsAt(plain)));
  const render::draw::Camera fitted = render::frame::panelCamera({s}, {survey}, 0);
  const render::draw::Bounds got = arrowsAt(fitted), view = fitted.view();
  CHECK(inside(view, got));
}

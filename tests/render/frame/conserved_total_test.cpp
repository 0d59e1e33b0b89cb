// A conserved total shown with the same digits throughout (conserved_total.cpp): the elastic bar of
// the issue, whose energy is kept to round-off, showed E = 3.51 J at its impact and 3.52 J after.
#include <doctest/doctest.h>

#include <set>

#include "render/draw/draw_list.h"
#include "render/frame/conserved_total.h"
#include "render/frame/energy_panel.h"
#include "render/frame/quantity_text.h"
#include "render/frame/survey.h"
#include "sim/scene/scene_build.h"
#include "support/drawn_scene.h"

using render::frame::ConservedTotal;
using render::frame::quantityText;

TEST_CASE("a total within round-off of its first value shows that value, rounded once") {
  // 3.515 J, kept to 1e-15: per frame it would print 3.51 and 3.52 by turns
  const double first = 3.5150000000000001;
  const ConservedTotal e(first, first);
  for (double now : {first, first - 4e-16, first + 4e-16, 3.51499999999999, 3.51500000000001})
    CHECK(quantityText("E", e.shown(now), "J") == quantityText("E", first, "J"));
  // a real change (a plastic impact, an event's work) shows its value now
  CHECK(e.shown(3.0) == 3.0);
  CHECK(e.shown(first * (1 + 1e-6)) == first * (1 + 1e-6));
  // a total that starts at zero stays "0" through round-off of the run's scale
  const ConservedTotal p(0.0, 2.0);
  CHECK(render::frame::numberText(p.shown(3e-17)) == "0");
  CHECK(p.shown(0.1) == 0.1);
}

TEST_CASE("the energy panel of an elastic impact writes one E throughout, before and after the impact") {
  // a box dropped spinning onto a floor, elastic, no gravity: E conserved to round-off by the event method
  const render::scene::Scene def = drawn_scene::load(
      "duration: 1.2\nworld: {restitution: 1}\nsim: {collisions: event}\n"
      "bodies:\n"
      "  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n"
      "  - {name: bar, shape: {box: [2.0, 0.2]}, mass: 1.3, position: [0, 1.3910538555739002], angle: 0.3, velocity: [0.1, "
      "-2.17], angular_velocity: 0.77}\n"
      "render: {energy: true}\n");
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  REQUIRE_FALSE(survey.impactTimes.empty());
  const render::frame::EnergyPanel panel(def, render::frame::cameraFor(def, survey), survey);
  sim::world::World world = sim::scene::buildWorld(def.model);
  std::set<std::string> shown;
  for (int k = 0; k <= 120; ++k) {
    world.advanceTo(k * 0.01);
    render::draw::DrawList list;
    panel.draw(world, list);
    for (const auto& c : list.calls())
      if (c.text.starts_with("E = ")) shown.insert(c.text);
  }
  CHECK(shown.size() == 1);
}

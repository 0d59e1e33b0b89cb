// impact_values: the held impact labeled n̂, j and v_n⁻ → v_n⁺ (the restitution law), events "j = … N·s".
#include <doctest/doctest.h>

#include "render/frame/impact_labels.h"
#include "render/frame/scene_run.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"

using render::draw::DrawList;

namespace {

// a ball falls at 2 m/s onto a floor without gravity, restitution 0.5: it touches at t = 0.25
const std::string kDrop = R"(
duration: 1
world: {restitution: 0.5}
bodies:
  - {name: ball, shape: {circle: 0.5}, position: [0, 1], velocity: [0, -2]}
  - {name: floor, shape: {box: [4, 0.5]}, position: [0, -0.25], static: true}
events:
  - {time: 0.6, body: ball, impulse: [1, 0]}
render: {size: [320, 180], impact_values: true}
)";

std::vector<std::string> textsAt(double t, sim::world::World* worldOut = nullptr, bool impactValues = true) {
  render::scene::Scene def = drawn_scene::load(kDrop);
  def.render.overlays.impactValues = impactValues;
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey);
  const DrawList list = run.drawListAt(t);
  if (worldOut) *worldOut = run.world();
  std::vector<std::string> out;
  for (const auto& c : list.calls())
    if (c.kind == DrawList::Kind::Text) out.push_back(c.text);
  return out;
}

bool has(const std::vector<std::string>& texts, const std::string& s) {
  return std::find(texts.begin(), texts.end(), s) != texts.end();
}

}  // namespace

TEST_CASE("the velocities text: v_n⁻ and v_n⁺ with true minus signs") {
  CHECK(render::frame::ImpactLabels::velocitiesText(-1.0, 0.5) == "v_n⁻ = −1.00 m/s → v_n⁺ = 0.500 m/s");
}

TEST_CASE("a plastic impact's round-off after speed reads 0, a slow real one keeps its digits") {
  CHECK(render::frame::ImpactLabels::velocitiesText(-2.0, 2.22e-16) == "v_n⁻ = −2.00 m/s → v_n⁺ = 0 m/s");
  CHECK(render::frame::ImpactLabels::velocitiesText(-2.0, 2e-5) == "v_n⁻ = −2.00 m/s → v_n⁺ = 2.00 × 10⁻⁵ m/s");
}

TEST_CASE("after the impact the afterimage says n̂, j and v_n⁻ → v_n⁺ = −c_r v_n⁻") {
  sim::world::World world;
  const auto texts = textsAt(0.3, &world);
  REQUIRE_FALSE(world.impacts.empty());
  const sim::world::ImpactRecord& r = world.impacts.front();
  // the restitution law of the notes: v_n⁺ = −c_r v_n⁻
  CHECK(r.vnBefore == doctest::Approx(-2.0));
  CHECK(r.vnAfter == doctest::Approx(1.0));
  CHECK(has(texts, "v_n⁻ = −2.00 m/s → v_n⁺ = 1.00 m/s"));
  CHECK(has(texts, "n̂"));
  CHECK(has(texts, "j"));  // on the ball only: the floor does not move
  CHECK(std::count(texts.begin(), texts.end(), "j") == 1);
}

TEST_CASE("an event's impulse is labeled with its value; without impact_values nothing is") {
  CHECK(has(textsAt(0.7), "j = 1.00 N·s"));
  // before the event there is nothing to label; with the overlay off, nothing after it either
  CHECK_FALSE(has(textsAt(0.2), "j = 1.00 N·s"));
  const std::vector<std::string> off = textsAt(0.7, nullptr, false);
  CHECK_FALSE(has(off, "j = 1.00 N·s"));
  CHECK_FALSE(has(off, "v_n⁻ = −2.00 m/s → v_n⁺ = 1.00 m/s"));
  CHECK_FALSE(has(off, "n̂"));
}

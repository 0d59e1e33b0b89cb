// The energy panel as draw calls: each bar's value as text, bar lengths on one scale, the panel in
// the frame's top-right corner, p and L as text.
#include <doctest/doctest.h>

#include "render/draw/draw_list.h"
#include "render/frame/energy_panel.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"

using render::draw::DrawList;
using render::draw::Role;
using sim::core::Vec2;

namespace {

// no gravity: ½mv² = 9 J and ½Iω² = 2 J all along, E = 11 J; 320×180 px: text 11 px, bars 88 px
const std::string kScene = R"(
duration: 1
bodies:
  - {name: ball, shape: {circle: 0.5}, mass: 2, inertia: 1, position: [0, 1], velocity: [3, 0], angular_velocity: 2}
render: {size: [320, 180], camera: {center: [0, 0], height: 10}, energy: true, momentum: true}
)";

DrawList panelAt(const std::string& yaml, render::draw::Camera* cameraOut = nullptr,
                 render::frame::RunSurvey* surveyOut = nullptr) {
  const render::scene::Scene def = drawn_scene::load(yaml);
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  if (surveyOut) *surveyOut = survey;
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  if (cameraOut) *cameraOut = camera;
  DrawList list;
  render::frame::EnergyPanel(def, camera, survey).draw(sim::scene::buildWorld(def.model), list);
  return list;
}

// a polygon's width in pixels
double widthPx(const DrawList::Call& c, const render::draw::Camera& camera) {
  return camera.toPixel(c.points[1]).x() - camera.toPixel(c.points[0]).x();
}

}  // namespace

TEST_CASE("the panel: ½mv² and ½Iω² of each moving body, the total, then p and L") {
  render::draw::Camera camera(Vec2::Zero(), 1.0, 2, 2);
  const DrawList list = panelAt(kScene, &camera);
  std::vector<std::string> texts;
  for (const auto& c : list.calls())
    if (c.kind == DrawList::Kind::Text) texts.push_back(c.text);
  CHECK(texts == std::vector<std::string>{"ball ½mv² = 9.00 J", "ball ½Iω² = 2.00 J", "E = 11.0 J", "p = (6.00, 0) kg·m/s",
                                          "L = −4.00 kg·m²/s"});
  // the panel first, its right edge half a line (5.5 px) in from the frame's; in 320 px it would reach
  // the clock, so it starts under it: half a line, the clock's line (1.25 × 11 px), half a line
  const auto& panel = list.calls()[0];
  CHECK(panel.style.role == Role::Panel);
  CHECK(camera.toPixel(panel.points[1]).x() == doctest::Approx(320 - 5.5));
  CHECK(camera.toPixel(panel.points[0]).y() == doctest::Approx(5.5 + 13.75 + 5.5));
  // without the clock, half a line in from the top
  std::string noClock = kScene;
  noClock.replace(noClock.find("energy: true"), 12, "energy: true, time: false");
  const DrawList alone = panelAt(noClock, &camera);
  CHECK(camera.toPixel(alone.calls()[0].points[0]).y() == doctest::Approx(5.5));
  // bars on one scale: the largest value of the run (E = 11 J) fills the 88 px
  const auto& kinetic = list.calls()[1];
  CHECK(kinetic.style.role == Role::KineticBar);
  CHECK(kinetic.style.body == 0);
  CHECK(widthPx(kinetic, camera) == doctest::Approx(88.0 * 9.0 / 11.0));
  CHECK(widthPx(list.calls()[3], camera) == doctest::Approx(88.0 * 2.0 / 11.0));
  CHECK(list.calls()[5].style.role == Role::TotalBar);
  CHECK(widthPx(list.calls()[5], camera) == doctest::Approx(88.0));
}

TEST_CASE("with gravity the potential energy has a bar; the run's negative values move the zero right") {
  std::string falling = kScene;
  falling.replace(falling.find("duration: 1"), 11, "duration: 1\nworld: {gravity: [0, -10]}");
  render::draw::Camera camera(Vec2::Zero(), 1.0, 2, 2);
  render::frame::RunSurvey survey;
  const DrawList list = panelAt(falling, &camera, &survey);
  // U = −m g·x: 20 J now, about −80 J at t = 1 when ½mv² is about 109 J: the scale spans the run's
  CHECK(survey.minEnergy == doctest::Approx(-80.0).epsilon(0.01));
  CHECK(survey.maxEnergy == doctest::Approx(109.0).epsilon(0.01));
  const double span = survey.maxEnergy - survey.minEnergy;
  CHECK(list.toText().find("\"U = 20.0 J\"") != std::string::npos);
  const DrawList::Call *kinetic = nullptr, *potential = nullptr;
  for (const auto& c : list.calls()) {
    if (c.style.role == Role::KineticBar) kinetic = &c;
    if (c.style.role == Role::PotentialBar) potential = &c;
  }
  REQUIRE(kinetic);
  REQUIRE(potential);
  CHECK(widthPx(*potential, camera) == doctest::Approx(88.0 * 20.0 / span));
  CHECK(camera.toPixel(potential->points[0]).x() == doctest::Approx(camera.toPixel(kinetic->points[0]).x()));
  const double zero = camera.toPixel(list.calls()[0].points[0]).x() + 0.4 * 11 - 88.0 * survey.minEnergy / span;
  CHECK(camera.toPixel(kinetic->points[0]).x() == doctest::Approx(zero));
}

TEST_CASE("momentum alone: a panel of two lines of text") {
  std::string alone = kScene;
  alone.replace(alone.find("energy: true"), 12, "energy: false");
  const DrawList list = panelAt(alone);
  REQUIRE(list.calls().size() == 3);
  CHECK(list.calls()[1].text == "p = (6.00, 0) kg·m/s");
  CHECK(list.calls()[2].text == "L = −4.00 kg·m²/s");
}

TEST_CASE("a value below the run's noise floor is 0, and the panel is as wide as its widest line") {
  const render::draw::Camera camera(Vec2::Zero(), 10.0, 640, 360);
  // the run's largest energy 4 J: 7.19 × 10⁻³⁸ J is round-off of a ball's spin, 1.10 × 10⁻⁴ J is not
  const render::frame::BarPanel panel({"ball ½Iω² = 4.00 J"}, {}, 0.0, 4.0, camera, 20.0);
  const std::vector<render::frame::EnergyBar> bars = {{"ball ½Iω²", 7.19e-38, Role::RotationalBar, 0},
                                                      {"bar ½Iω²", 1.10e-4, Role::RotationalBar, 1},
                                                      {"E", 4.0, Role::TotalBar, -1}};
  DrawList estimated, measured;
  panel.draw(bars, {}, estimated);
  std::vector<std::string> texts;
  for (const auto& c : estimated.calls())
    if (c.kind == DrawList::Kind::Text) texts.push_back(c.text);
  CHECK(texts == std::vector<std::string>{"ball ½Iω² = 0 J", "bar ½Iω² = 1.10 × 10⁻⁴ J", "E = 4.00 J"});
  // bars under half a pixel are not drawn: the panel, E's bar and the three texts
  CHECK(estimated.calls().size() == 1 + 1 + 3);
  // a frame whose text is wider than the estimate widens the panel to its widest line, leftwards
  panel.draw(bars, {}, measured, [](const std::string& s) { return s.find("10⁻⁴") != std::string::npos ? 400 : 100; });
  const double before = widthPx(estimated.calls()[0], camera), after = widthPx(measured.calls()[0], camera);
  CHECK(after == doctest::Approx(400 + (8.0 + 0.5 + 0.8) * 20.0));
  CHECK(after > before);
  CHECK(camera.toPixel(measured.calls()[0].points[1]).x() == doctest::Approx(640 - 10.0));
}

// The draw-list level of a 3D frame (no GL): what a frame shows, as calls. A free symmetric top:
// the solid at its pose, L's arrow fixed in space while ω's wanders about it at a constant length,
// the state written as text, the energy panel's total unchanged; an overlay left out of the block
// is left out of the list.
#include "render/frame3d/scene_run3d.h"

#include <doctest/doctest.h>

#include <algorithm>

#include "sim/yaml/scene_source.h"

using namespace render::frame3d;
using namespace render::draw3d;
using render::draw::DrawList;
using render::draw::Role;
using render::draw3d::DrawList3d;
using sim::core::Vec2;

namespace {

const char* const kTop = R"(
dimensions: 3
duration: 2
sim: {integrator: splitting, dt: 0.001}
bodies:
  - {name: top, shape: {ellipsoid: [0.3, 0.3, 0.1]}, density: 100, orientation: {axis: [1, 0, 0], angle: 0.3},
     angular_velocity: [0.5, 0, 4], label: top}
render:
  size: [640, 360]
  energy: true
  arrows:
    - {body: top, show: omega}
    - {body: top, show: angular_momentum}
    - {body: top, show: omega_path}
    - {body: top, show: state}
)";

struct Frame {
  DrawList3d list;
  std::vector<std::string> lines;
};

// the scene's draw list at time t, from a fresh run through its own camera
Frame frameAt(const std::string& yaml, double t) {
  const render::scene3d::Scene def = render::scene3d::readScene(sim::yaml::sceneSourceText(yaml, "inline.yaml"));
  const RunSurvey3d survey = surveyRun(def);
  SceneRun3d run(def, cameraFor(def, survey), survey);
  Frame f{run.drawListAt(t), {}};
  f.lines = f.list.lines();
  return f;
}

// the arrow drawn in `role`, tail and head in overlay pixels
std::pair<Vec2, Vec2> arrowOf(const Frame& f, Role role) {
  for (const DrawList::Call& c : f.list.overlayCalls().calls())
    if (c.kind == DrawList::Kind::Arrow && c.style.role == role) return {c.points[0], c.points[1]};
  FAIL("no arrow of role " << render::draw::info(role).name);
  return {};
}

bool hasText(const Frame& f, const std::string& text) {
  return std::any_of(f.list.overlayCalls().calls().begin(), f.list.overlayCalls().calls().end(),
                     [&](const DrawList::Call& c) { return c.kind == DrawList::Kind::Text && c.text == text; });
}

}  // namespace

TEST_CASE("a 3D frame's draw list: the solid, L fixed while ω wanders, the state as text, the energy panel") {
  const Frame start = frameAt(kTop, 0.0), later = frameAt(kTop, 1.3);
  INFO(later.list.toText());
  REQUIRE_FALSE(start.lines.empty());
  CHECK(start.lines.front().rfind("solid Body#0 ellipsoid 0.3 0.3 0.1 x=(0,0,0) R=(1,0,0)", 0) == 0);
  // the ellipsoid turned between the two: its rows differ
  CHECK(later.lines.front() != start.lines.front());
  const auto [l0Tail, l0Head] = arrowOf(start, Role::AngularMomentum);
  const auto [l1Tail, l1Head] = arrowOf(later, Role::AngularMomentum);
  CHECK((l0Tail - l1Tail).norm() < 1e-6);
  CHECK((l0Head - l1Head).norm() < 1e-3);  // the splitting keeps L to round-off: the same pixel
  const auto [w0Tail, w0Head] = arrowOf(start, Role::AngularVelocity);
  const auto [w1Tail, w1Head] = arrowOf(later, Role::AngularVelocity);
  CHECK((w0Head - w1Head).norm() > 5.0);  // ω has moved on its cone, pixels apart
  // ω's path is drawn from the center: segments of its role, faded
  const auto& calls = later.list.overlayCalls().calls();
  const long pathSegments = std::count_if(calls.begin(), calls.end(), [](const DrawList::Call& c) {
    return c.kind == DrawList::Kind::Segment && c.style.role == Role::AngularVelocity && c.style.opacity < 1.0;
  });
  CHECK(pathSegments > 10);
  // x and q as text; |q| = 1 under the splitting
  CHECK(hasText(start, "x = (0, 0, 0) m"));
  CHECK(hasText(start, "q = [0.989, 0.149, 0.000, 0.000]"));
  CHECK(hasText(later, "|q| = 1.000000"));
  CHECK(hasText(later, "t = 1.300 s"));
  // the energy panel's total, the same at both times (a free body, E kept to 1e-5)
  std::string total;
  for (const DrawList::Call& c : start.list.overlayCalls().calls())
    if (c.kind == DrawList::Kind::Text && c.text.rfind("E = ", 0) == 0) total = c.text;
  REQUIRE_FALSE(total.empty());
  CHECK(hasText(later, total));
  // the world's axes, bottom right, labeled
  CHECK(hasText(start, "z"));
}

TEST_CASE("what the render: block leaves out, the draw list leaves out") {
  std::string plain = kTop;
  plain.erase(plain.find("  arrows:"));
  const Frame f = frameAt(plain + "  world_axes: false\n", 1.0);
  for (const DrawList::Call& c : f.list.overlayCalls().calls()) {
    CHECK(c.style.role != Role::AngularMomentum);
    CHECK(c.style.role != Role::AxisZ);
  }
  CHECK_FALSE(hasText(f, "|q| = 1.000000"));
}

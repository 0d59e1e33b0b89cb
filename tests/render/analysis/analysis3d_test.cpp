// Speed against accuracy on a 3D scene: the sweep's work-precision slopes give each classic
// integrator's order (1, 1, 2, 4) and the splitting's (2); the stability search finds where
// explicit Euler without normalization stops holding |q| to 1 %, against its closed form.
#include "render/analysis/analysis3d.h"

#include <doctest/doctest.h>

#include <cmath>

#include "sim/yaml3d/scene_yaml.h"

namespace {

namespace w3 = sim::world3d;

// a box on a spring to the world from one of its corners, under gravity, over 1 s: translation and
// rotation coupled, ω wandering
const char* kSpringBox = R"(
dimensions: 3
duration: 1
world: {gravity: [0, 0, -9.81]}
bodies:
  - {name: box, shape: {box: [0.2, 0.4, 0.6]}, mass: 1, position: [0.3, 0, -0.8], angular_velocity: [1, 2, 3]}
forces:
  - {type: spring, body: box, point: [0.1, 0.2, 0.3], anchor: [0, 0, 0], stiffness: 40, rest_length: 0.5}
)";

// least-squares slope of log(error) against log(dt)
double slope(const std::vector<render::analysis::Sweep3dRow>& rows) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(rows.size());
  for (const render::analysis::Sweep3dRow& r : rows) {
    const double x = std::log(r.dt), y = std::log(r.error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

TEST_CASE("3D sweep: the work-precision slopes give each integrator's order, 1, 1, 2, 4 and the splitting's 2 (±0.3)") {
  const sim::scene3d::SceneDef def = sim::yaml3d::loadSceneText(kSpringBox, "inline.yaml");
  struct Case {
    w3::Integrator method;
    double from;  // the largest step of four halvings, in each method's asymptotic range
    double order;
  };
  const render::analysis::Sweep3dReference reference = render::analysis::sweepReference3d(def, 2.5e-4);
  CHECK(reference.name.find("rk4") != std::string::npos);
  for (const Case& c :
       {Case{w3::Integrator::ExplicitEuler, 2e-3, 1}, Case{w3::Integrator::SymplecticEuler, 2e-3, 1},
        Case{w3::Integrator::Midpoint, 8e-3, 2}, Case{w3::Integrator::Rk4, 4e-2, 4}, Case{w3::Integrator::Splitting, 8e-3, 2}}) {
    std::vector<render::analysis::Sweep3dRow> rows;
    for (double h = c.from; h > c.from / 10.0; h /= 2.0)
      rows.push_back(render::analysis::runSweepCase3d(def, c.method, h, reference, 1));
    const double measured = slope(rows);
    MESSAGE(w3::kIntegratorNames.name(c.method), ": slope ", measured);
    CHECK(measured == doctest::Approx(c.order).epsilon(0.3 / c.order));
    for (const render::analysis::Sweep3dRow& r : rows) {
      CHECK(r.metrics.finite);
      CHECK(r.steps == std::lround(1.0 / r.dt));
    }
  }
}

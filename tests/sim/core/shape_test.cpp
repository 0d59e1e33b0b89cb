#include "sim/core/shape.h"

#include <doctest/doctest.h>

#include <numbers>
#include <stdexcept>

#include "sim/scene/scene_build.h"

using sim::core::Vec2;

TEST_CASE("box mass properties match the closed form") {
  const sim::core::Shape box = sim::core::makeBox(2.0, 0.5);
  const sim::core::AreaProperties p = sim::core::areaProperties(box);
  CHECK(p.area == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(p.centroid.norm() < 1e-15);
  // I = m (w² + h²) / 12 at unit density
  CHECK(p.secondMoment == doctest::Approx((4.0 + 0.25) / 12.0).epsilon(1e-14));
}

TEST_CASE("a right triangle's centroid and moment, and the centroid shift of its body") {
  const double a = 3.0, b = 2.0;
  const sim::core::Shape tri = sim::core::makePolygon({{0, 0}, {a, 0}, {0, b}});
  const sim::core::AreaProperties p = sim::core::areaProperties(tri);
  CHECK(p.area == doctest::Approx(a * b / 2).epsilon(1e-15));
  CHECK(p.centroid.x() == doctest::Approx(a / 3).epsilon(1e-15));
  CHECK(p.centroid.y() == doctest::Approx(b / 3).epsilon(1e-15));
  // about the centroid: I = m (a² + b²) / 18
  CHECK(p.secondMoment == doctest::Approx(p.area * (a * a + b * b) / 18).epsilon(1e-14));

  // the body origin moves to the centroid; points written in the shape's frame move with it
  sim::scene::BodyDef def;
  def.name = "tri";
  def.shape = tri;
  def.density = 2.0;
  const sim::scene::MassProperties mp = sim::scene::massProperties(def);
  CHECK(mp.mass == doctest::Approx(2.0 * a * b / 2).epsilon(1e-15));
  CHECK(mp.inertia == doctest::Approx(mp.mass * (a * a + b * b) / 18).epsilon(1e-14));
  const sim::core::Shape centered = sim::core::shifted(tri, mp.centroid);
  CHECK(sim::core::areaProperties(centered).centroid.norm() < 1e-15);
  CHECK((centered.vertices[0] - Vec2(-a / 3, -b / 3)).norm() < 1e-15);
}

TEST_CASE("a regular polygon's moment: I = m R² (1 + 2 cos²(π/n)) / 6") {
  for (int n : {3, 5, 6, 12}) {
    std::vector<Vec2> v;
    const double radius = 1.7;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * k / n + 0.3;
      v.push_back({2.0 + radius * std::cos(t), -1.0 + radius * std::sin(t)});
    }
    const sim::core::AreaProperties p = sim::core::areaProperties(sim::core::makePolygon(v));
    const double c = std::cos(std::numbers::pi / n);
    CHECK(p.area == doctest::Approx(0.5 * n * radius * radius * std::sin(2 * std::numbers::pi / n)).epsilon(1e-13));
    CHECK((p.centroid - Vec2(2.0, -1.0)).norm() < 1e-13);
    CHECK(p.secondMoment == doctest::Approx(p.area * radius * radius * (1 + 2 * c * c) / 6).epsilon(1e-13));
  }
}

TEST_CASE("a circle: I = m r² / 2") {
  const sim::core::AreaProperties p = sim::core::areaProperties(sim::core::makeCircle(0.5));
  CHECK(p.area == doctest::Approx(std::numbers::pi * 0.25).epsilon(1e-15));
  CHECK(p.secondMoment == doctest::Approx(p.area * 0.25 / 2).epsilon(1e-15));
}

TEST_CASE("polygons are stored counter-clockwise with outward unit normals, whatever the winding") {
  const sim::core::Shape cw = sim::core::makePolygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
  for (size_t i = 0; i < cw.vertices.size(); ++i) {
    const Vec2 e = cw.vertices[(i + 1) % 4] - cw.vertices[i];
    CHECK(sim::core::cross(e, cw.vertices[(i + 2) % 4] - cw.vertices[(i + 1) % 4]) > 0);
    CHECK(cw.normals[i].norm() == doctest::Approx(1.0));
    CHECK(cw.normals[i].dot(e) == doctest::Approx(0.0));
    // outward: the centroid is behind every edge
    CHECK(cw.normals[i].dot(Vec2(0.5, 0.5) - cw.vertices[i]) < 0);
  }
}

TEST_CASE("non-convex, degenerate and self-intersecting polygons are rejected with the reason") {
  auto reason = [](std::vector<Vec2> v) {
    try {
      sim::core::makePolygon(std::move(v));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(reason({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}).find("non-convex") != std::string::npos);
  CHECK(reason({{0, 0}, {1, 0}, {2, 0}, {1, 1}}).find("degenerate") != std::string::npos);
  CHECK(reason({{0, 0}, {1, 0}, {1, 0}, {0, 1}}).find("coincide") != std::string::npos);
  CHECK(reason({{0, 0}, {1, 0}}).find("at least 3") != std::string::npos);
  CHECK(reason({{0, 0}, {1, 1}, {2, 2}}).find("degenerate") != std::string::npos);
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double t = 2 * std::numbers::pi * (2 * k % 5) / 5;
    star.push_back({std::cos(t), std::sin(t)});
  }
  CHECK(reason(star).find("self-intersecting") != std::string::npos);
  CHECK_THROWS_AS(sim::core::makeBox(0, 1), std::invalid_argument);
  CHECK_THROWS_AS(sim::core::makeCircle(-1), std::invalid_argument);
}

// The golden: block: its defaults, its keys read, and each fault at its line.
#include <doctest/doctest.h>

#include "render/golden/golden_def.h"
#include "sim/yaml/scene_source.h"
#include "support/scene_error_check.h"

using namespace render::golden;

namespace {

GoldenDef read(const std::string& text, const std::string& file = "g.yaml") {
  return readGolden(sim::yaml::sceneSourceText("bodies: [{name: b, shape: {circle: 1}}]\n" + text, file), 2.0);
}

}  // namespace

TEST_CASE("without a golden: block, the end and the impacts at 640x360, tolerances as documented") {
  const GoldenDef d = read("");
  CHECK(d.at.empty());
  CHECK(d.impacts);
  CHECK(d.width == 640);
  CHECK(d.height == 360);
  CHECK(d.tolerance.position == 1e-9);
  CHECK(d.pixelTolerance == 24);
  CHECK(d.pixelFraction == 0.002);
}

TEST_CASE("every key of the block is read") {
  const GoldenDef d = read(
      "golden: {at: [0.5, 2], impacts: false, size: [320, 180], tolerance: {position: 1e-6, angle: 2e-6, velocity: 3e-6},"
      " pixel_tolerance: 10, pixel_fraction: 0.01}\n");
  CHECK(d.at == std::vector<double>{0.5, 2});
  CHECK_FALSE(d.impacts);
  CHECK(d.width == 320);
  CHECK(d.height == 180);
  CHECK(d.tolerance.position == 1e-6);
  CHECK(d.tolerance.angle == 2e-6);
  CHECK(d.tolerance.velocity == 3e-6);
  CHECK(d.pixelTolerance == 10);
  CHECK(d.pixelFraction == 0.01);
}

TEST_CASE("a bad golden: block is refused at its line and column") {
  const auto load = [](const std::string& text, const std::string& file, const std::string&) { return read(text, file); };
  scene_errors::expectSceneError(load, "g.yaml", "golden: {at: [3]}\n", 2, 15, {"outside the scene's duration"});
  scene_errors::expectSceneError(load, "g.yaml", "golden: {frames: [1]}\n", 2, 10, {"unknown key 'frames'"});
  scene_errors::expectSceneError(load, "g.yaml", "golden: {size: [640]}\n", 2, 16, {"[width, height]"});
  scene_errors::expectSceneError(load, "g.yaml", "golden: {pixel_tolerance: 256}\n", 2, 27, {"from 0 to 255"});
  scene_errors::expectSceneError(load, "g.yaml", "golden: {tolerance: {position: -1}}\n", 2, 32, {"'position'"});
}

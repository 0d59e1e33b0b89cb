// A golden frame of each lecture scene (scenes/lecture/*.yaml, the 3D ones in perspective): its first
// variant (or the scene itself) at half its duration, drawn 640 × 360, against
// tests/golden/lecture/<scene>.png. Half
// the duration shows each scene's idea under way: the held impacts, the overlays, the failures.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "render/frame/scene_run.h"
#include "render/frame3d/scene_run3.h"
#include "sim/yaml/scene_yaml.h"
#include "support/drawn_scene.h"
#include "support/golden_compare.h"

namespace fs = std::filesystem;

namespace {

// the frame size of the golden images, pixels: large enough for the overlays' text (11 px at least)
// to leave the bodies room beside the energy panel
constexpr int kWidth = 640, kHeight = 360;

std::vector<fs::path> lectureScenes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(golden::kSource / "scenes" / "lecture"))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// a 3D scene's frame, as the 2D ones: its first variant at half its duration
render::draw::Image frame3d(const std::string& file, render::draw::GlContext& gl, render::draw::TextRenderer& text) {
  const auto load = [&](const std::string& variant) {
    return render::scene3d::readScene(sim::yaml::readSceneSource(file, variant), {{"stability"}, {}});
  };
  const render::scene3d::Scene base = load("");
  render::scene3d::Scene def = load(base.model.variantNames.empty() ? "" : base.model.variantNames.front());
  def.render.width = kWidth;
  def.render.height = kHeight;
  const render::frame3d::RunSurvey3 survey = render::frame3d::surveyRun(def);
  render::frame3d::SceneRun3 run(def, render::frame3d::cameraFor(def, survey), survey, &gl, &text);
  return run.frameAt(0.5 * def.model.duration);
}

}  // namespace

TEST_CASE("golden: a frame of every lecture scene at half its duration") {
  const std::vector<fs::path> files = lectureScenes();
  // the pack has a scene for each of the notes' ten ideas (the last one in three files)
  REQUIRE(files.size() >= 10);
  render::draw::GlContext gl(kWidth, kHeight);
  render::draw::TextRenderer text;
  for (const fs::path& file : files) {
    CAPTURE(file.string());
    if (sim::yaml::readSceneSource(file.string()).dimensions == 3) {
      golden::checkGolden("lecture/" + file.stem().string(), frame3d(file.string(), gl, text));
      continue;
    }
    const render::scene::Scene base = drawn_scene::loadFile(file.string());
    const std::string variant = base.model.variantNames.empty() ? "" : base.model.variantNames.front();
    render::scene::Scene def = drawn_scene::loadFile(file.string(), variant);
    def.render.width = kWidth;
    def.render.height = kHeight;
    const render::frame::RunSurvey survey = render::frame::surveyRun(def);
    render::frame::SceneRun run(def, render::frame::cameraFor(def, survey), survey, &gl, &text);
    golden::checkGolden("lecture/" + file.stem().string(), run.frameAt(0.5 * def.model.duration));
  }
}

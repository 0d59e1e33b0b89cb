// A golden frame of each lecture scene (scenes/lecture/*.yaml, the 3D ones in perspective): its first
// variant (or the scene itself) at half its duration, drawn 640 × 360, against
// tests/golden/lecture/<scene>.png. Half
// the duration shows each scene's idea under way: the held impacts, the overlays, the failures.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "render/frame/pixel_draw_list.h"
#include "render/frame/scene_run.h"
#include "render/frame3d/scene_run3d.h"
#include "render/scene/scene_style.h"
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
    return render::scene3d::readScene(sim::yaml::readSceneSource(file, variant), {{"stability", "golden"}, {}});
  };
  const render::scene3d::Scene base = load("");
  render::scene3d::Scene def = load(base.model.variantNames.empty() ? "" : base.model.variantNames.front());
  def.render.width = kWidth;
  def.render.height = kHeight;
  const render::frame3d::RunSurvey3d survey = render::frame3d::surveyRun(def);
  render::frame3d::SceneRun3d run(def, render::frame3d::cameraFor(def, survey), survey, &gl, &text);
  return run.frameAt(0.5 * def.model.duration);
}

}  // namespace

namespace {

// a text's box as the text renderer draws it (text.cpp): a label centered on its point, a caption
// with its top-left corner there, whole pixels
render::frame::PixelBox drawnBox(const render::draw::DrawList::Call& call, const render::draw::Camera& camera,
                                 render::draw::TextRenderer& text, int fontPx) {
  const render::draw::TextBox box = text.measure(call.text, fontPx);
  const bool caption = call.style.role == render::draw::Role::Caption;
  return render::frame::textBox(camera.toPixel(call.points[0]),
                                caption ? render::draw::Anchor::TopLeft : render::draw::Anchor::Center, box.width,
                                box.ascent + box.descent);
}

// every text of the frames at `times` (ascending): no two boxes overlap, and no label covers the
// anchor of another (what it names); returns how many texts the frames have
size_t checkTextsApart(const render::scene::Scene& def, const std::vector<double>& times, render::draw::TextRenderer& text) {
  const render::frame::RunSurvey survey = render::frame::surveyRun(def);
  const render::draw::Camera camera = render::frame::cameraFor(def, survey);
  render::frame::SceneRun run(def, camera, survey, nullptr, &text);
  const int fontPx = render::scene::fontSizeFor(def.render, camera.heightPx());
  size_t count = 0;
  for (double t : times) {
    std::vector<render::frame::PlacedText> placed;
    const render::draw::DrawList list = run.drawListAt(t, 0, &placed);
    std::vector<render::frame::PixelBox> boxes;
    std::vector<std::string> texts;
    for (const render::draw::DrawList::Call& c : list.calls()) {
      // labels reach the canvas placed, as text
      CHECK(c.kind != render::draw::DrawList::Kind::Label);
      if (c.kind != render::draw::DrawList::Kind::Text) continue;
      boxes.push_back(drawnBox(c, camera, text, fontPx));
      texts.push_back(c.text);
    }
    REQUIRE(boxes.size() == placed.size());
    for (size_t i = 0; i < boxes.size(); ++i)
      for (size_t j = i + 1; j < boxes.size(); ++j) {
        INFO("'" << texts[i] << "' and '" << texts[j] << "' at t = " << t);
        CHECK_FALSE(boxes[i].overlaps(boxes[j]));
      }
    // (text fixed to the frame, the clock and the caption, has no anchor and may lie over one; a body's
    // name and a zero-length arrow's value at its center share theirs)
    for (size_t i = 0; i < placed.size(); ++i) {
      if (!placed[i].anchor) continue;
      for (size_t j = 0; j < boxes.size(); ++j) {
        INFO("'" << texts[j] << "' covers the anchor of '" << texts[i] << "' at t = " << t);
        if (j != i && placed[j].anchor && (*placed[j].anchor - *placed[i].anchor).norm() > 1.0)
          CHECK_FALSE(boxes[j].contains(*placed[i].anchor));
      }
    }
    count += boxes.size();
  }
  return count;
}

}  // namespace

TEST_CASE("every text of every lecture scene stands apart: no two overlap, none covers what another names") {
  render::draw::TextRenderer text;
  size_t frames = 0, texts = 0;
  for (const fs::path& file : lectureScenes()) {
    // (the 2D frames' texts: a 3D frame's are its state text and arrow labels, placed by frame3d)
    if (sim::yaml::readSceneSource(file.string()).dimensions == 3) continue;
    const render::scene::Scene base = drawn_scene::loadFile(file.string());
    std::vector<std::string> variants = base.model.variantNames;
    if (variants.empty()) variants.push_back("");
    for (const std::string& variant : variants) {
      CAPTURE(file.string());
      CAPTURE(variant);
      render::scene::Scene def = drawn_scene::loadFile(file.string(), variant);
      def.render.width = kWidth;
      def.render.height = kHeight;
      // the golden frame's instant, the poster's, the poll panels', and every tenth of the run
      std::vector<double> times = {0.5 * def.model.duration, def.model.duration};
      for (double t : base.render.panels.times)
        if (t <= def.model.duration) times.push_back(t);
      for (int k = 0; k < 10; ++k) times.push_back(0.1 * k * def.model.duration);
      std::sort(times.begin(), times.end());
      times.erase(std::unique(times.begin(), times.end()), times.end());
      texts += checkTextsApart(def, times, text);
      frames += times.size();
    }
  }
  MESSAGE(texts << " texts on " << frames << " frames");
  CHECK(frames >= 200);
}

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

// The stills' draw lists in pixels (still_draw_lists.cpp, render/frame/pixel_draw_list.cpp): a sheet's
// cells moved to their places with its titles and caption, each text with its box; then what a slide
// promises, held on them over the whole 2D lecture pack: frames at the start, the middle and the end of
// every variant, and every poll sheet (the scene's `panels:` and at its impacts).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "render/video/render_plan.h"
#include "render/video/still_draw_lists.h"
#include "sim/yaml/scene_source.h"
#include "support/drawn_scene.h"
#include "support/slide_checks.h"

namespace fs = std::filesystem;
using render::frame::PixelCall;
using render::frame::PixelDrawList;
using render::video::RenderPlan;

namespace {

// two variants of a ball bouncing off a wall, with the energy panel and a caption
const std::string kLesson =
    drawn_scene::bounce("1",
                        "render: {energy: true, caption: \"A ball and a wall.\", size: [640, 360]}\nvariants:\n  A: {}\n  slow: "
                        "{bodies: [{name: ball, velocity: [0.5, 0]}]}\n");

render::video::LoadVariant lesson() {
  return [](const std::string& variant) { return drawn_scene::load(kLesson, variant, "lesson.yaml"); };
}

std::vector<PixelDrawList> drawLists(const RenderPlan& plan) {
  std::vector<PixelDrawList> lists(plan.stills->shots.size());
  render::video::stillDrawLists(*plan.stills, [&](size_t k, const PixelDrawList& l) { lists[k] = l; });
  return lists;
}

const PixelCall* find(const PixelDrawList& list, const std::string& kind, const std::string& pen, const std::string& text = "") {
  for (const PixelCall& c : list.calls)
    if (c.kind == kind && c.pen == pen && (text.empty() || c.text == text)) return &c;
  return nullptr;
}

}  // namespace

TEST_CASE("a frame's draw list is in its pixels, each text with the box it is drawn in") {
  const RenderPlan plan =
      render::video::planStills(lesson(), {.file = "lesson.yaml", .variant = "A", .times = {0.25}, .drawList = true});
  REQUIRE(plan.stills->shots.size() == 1);
  CHECK(plan.stills->shots[0].drawListPath ==
        plan.stills->shots[0].path.substr(0, plan.stills->shots[0].path.size() - 4) + ".json");
  const PixelDrawList list = drawLists(plan).front();
  CHECK(list.width == 640);
  CHECK(list.height == 360);
  // the ball at its place in pixels, its radius in pixels
  const PixelCall* ball = find(list, "circle", "Body#0");
  REQUIRE(ball);
  const render::draw::Camera& camera = plan.stills->camera;
  const sim::core::Vec2 center = camera.toPixel({0.25, 0.0});
  CHECK(ball->numbers[0] == doctest::Approx(center.x()));
  CHECK(ball->numbers[1] == doctest::Approx(center.y()));
  CHECK(ball->numbers[2] == doctest::Approx(0.25 / camera.pixelSize()));
  // the clock: a caption whose box starts at its point, in the top-left corner
  const PixelCall* clock = find(list, "text", "Caption", "t = 0.250 s");
  REQUIRE(clock);
  REQUIRE(clock->box);
  CHECK(clock->box->left == std::lround(clock->numbers[0]));
  CHECK(clock->box->top == std::lround(clock->numbers[1]));
  CHECK(clock->box->right > clock->box->left + 50);
  // the panel, a polygon of its own pen
  CHECK(find(list, "polygon", "Panel"));
  for (const std::string& fault : slide_checks::faults(list)) FAIL_CHECK(fault);
}

TEST_CASE("a sheet's draw list holds each cell's calls moved to its place, then its titles and caption") {
  const RenderPlan plan = render::video::planStills(
      lesson(),
      {.file = "lesson.yaml", .times = {0.25}, .panels = true, .size = render::video::FrameSize{1280, 720}, .drawList = true});
  const render::frame::PanelGrid& grid = plan.stills->grid;
  const PixelDrawList sheet = drawLists(plan).front();
  CHECK(sheet.width == 1280);
  CHECK(sheet.height == 720);
  // the second cell's ball lies in the second cell
  std::vector<const PixelCall*> balls;
  for (const PixelCall& c : sheet.calls)
    if (c.kind == "circle" && c.pen == "Body#0") balls.push_back(&c);
  REQUIRE(balls.size() == 2);
  CHECK(balls[0]->numbers[0] < grid.frameX(1));
  CHECK(balls[1]->numbers[0] > grid.frameX(1));
  CHECK(balls[1]->numbers[1] == doctest::Approx(balls[0]->numbers[1]).epsilon(0.2));
  // the titles over their cells, the caption under the grid
  const PixelCall* a = find(sheet, "text", "Caption", "A");
  const PixelCall* b = find(sheet, "text", "Caption", "B: slow");
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->box->bottom <= grid.frameY(0));
  CHECK(b->box->left > grid.frameX(1));
  const PixelCall* caption = find(sheet, "text", "Caption", "A ball and a wall.");
  REQUIRE(caption);
  CHECK(caption->box->top >= grid.frameY(0) + grid.frameHeight);
  for (const std::string& fault : slide_checks::faults(sheet)) FAIL_CHECK(fault);
}

TEST_CASE("the slide checks see what a slide must not show") {
  PixelDrawList list{100, 100, {}};
  const render::draw::Pen caption{render::draw::Role::Caption, -1, 1.0};
  const render::draw::Pen body{render::draw::Role::Body, 0, 1.0};
  const render::draw::Pen panel{render::draw::Role::Panel, -1, 1.0};
  list.calls.push_back({"text", "Caption", "#000000", "A: A: center", {0, 0}, render::frame::PixelBox{0, 0, 50, 10}, caption});
  list.calls.push_back(
      {"text", "Caption", "#000000", "t = 0.765077 s", {40, 5}, render::frame::PixelBox{40, 5, 90, 15}, caption});
  list.calls.push_back(
      {"text", "Caption", "#000000", "E = 7.19 × 10⁻³⁸ J", {0, 50}, render::frame::PixelBox{0, 50, 120, 60}, caption});
  list.calls.push_back({"text", "Caption", "#000000", "and…", {0, 80}, render::frame::PixelBox{0, 80, 20, 90}, caption});
  list.calls.push_back({"polygon", "Panel", "#f2f2f2", "", {60, 60, 90, 60, 90, 90, 60, 90}, {}, panel});
  list.calls.push_back({"circle", "Body#0", "#3b6ea5", "", {95, 95, 10}, {}, body});
  list.calls.push_back({"text", "Caption", "#000000", "E = 2 J", {62, 62}, render::frame::PixelBox{62, 62, 88, 72}, caption});
  list.calls.push_back({"text", "Caption", "#000000", "t = 1 s", {50, 75}, render::frame::PixelBox{50, 75, 70, 85}, caption});
  const std::vector<std::string> faults = slide_checks::faults(list);
  const auto has = [&](const std::string& part) {
    return std::any_of(faults.begin(), faults.end(), [&](const std::string& f) { return f.find(part) != std::string::npos; });
  };
  CHECK(has("repeats its letter"));
  CHECK(has("overlaps"));
  CHECK(has("more than 3 decimals"));
  CHECK(has("round-off"));
  CHECK(has("leaves the image"));
  CHECK(has("is cut"));
  CHECK(has("the panel meets Body#0"));
  // the panel's own row lies in it; the clock half under it runs into it
  CHECK(has("'t = 1 s' runs into the panel"));
  CHECK_FALSE(has("'E = 2 J' runs into"));
  CHECK(faults.size() == 8);
}

namespace {

std::vector<fs::path> packScenes2d() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(RIGIDREEL_SOURCE_DIR) / "scenes" / "lecture"))
    if (entry.path().extension() == ".yaml" && sim::yaml::readSceneSource(entry.path().string()).dimensions == 2)
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

render::video::LoadVariant fileLoader(const std::string& file) {
  return [file](const std::string& variant) { return drawn_scene::loadFile(file, variant); };
}

// every still of `plan` keeps a slide's promises; returns how many
size_t checkStills(const RenderPlan& plan) {
  size_t count = 0;
  render::video::stillDrawLists(*plan.stills, [&](size_t k, const PixelDrawList& list) {
    CAPTURE(plan.stills->shots[k].path);
    for (const std::string& fault : slide_checks::faults(list)) FAIL_CHECK(fault);
    ++count;
  });
  return count;
}

}  // namespace

TEST_CASE("every frame of the 2D lecture pack keeps a slide's promises: at the start, the middle and the end of each variant") {
  size_t stills = 0;
  for (const fs::path& file : packScenes2d()) {
    const render::scene::Scene base = drawn_scene::loadFile(file.string());
    std::vector<std::string> variants = base.model.variantNames;
    if (variants.empty()) variants.push_back("");
    for (const std::string& variant : variants) {
      const double d = drawn_scene::loadFile(file.string(), variant).model.duration;
      stills += checkStills(render::video::planStills(fileLoader(file.string()),
                                                      {.file = file.string(), .variant = variant, .times = {0, 0.5 * d, d}}));
    }
  }
  CHECK(stills >= 3 * 12);
}

TEST_CASE("every poll sheet of the 2D lecture pack keeps a slide's promises: its panels' times and its impacts") {
  size_t sheets = 0;
  for (const fs::path& file : packScenes2d()) {
    const render::video::LoadVariant load = fileLoader(file.string());
    const render::scene::Scene base = load("");
    if (base.model.variantNames.empty()) continue;
    CAPTURE(file.string());
    const RenderPlan lecture = render::video::planLecture(load, {.file = file.string()});
    if (lecture.stills) sheets += checkStills(lecture);
    bool impacts = true;
    for (const render::video::PlannedVariant& v : lecture.variants) impacts = impacts && !v.survey.impactTimes.empty();
    if (impacts) sheets += checkStills(render::video::planStills(load, {.file = file.string(), .impacts = true, .panels = true}));
  }
  CHECK(sheets >= 8);
}

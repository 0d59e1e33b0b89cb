// The stills' draw lists in pixels (still_draw_lists.cpp, render/frame/pixel_draw_list.cpp): a frame's
// calls in its pixels, a sheet's cells moved to their places with its titles and caption, each text
// with its box; and the checks of what a slide promises, seeing each fault.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "render/video/render_plan.h"
#include "render/video/still_draw_lists.h"
#include "support/drawn_scene.h"
#include "support/slide_checks.h"

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
  CHECK(faults.size() == 7);
}

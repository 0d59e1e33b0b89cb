// An image's draw list in its pixels (pixel_draw_list.cpp): points through the camera, y down; a
// half-plane's normal turned with y; a circle's radius in pixels; each text's box as TextRenderer
// draws it; calls moved into a sheet's cell; the JSON `snapshot --draw-list` writes.
#include "render/frame/pixel_draw_list.h"

#include <doctest/doctest.h>

#include <sstream>

using namespace render::draw;
using render::frame::PixelBox;
using render::frame::PixelDrawList;

namespace {

// 10 px per metre: a 200 × 100 frame of the world [-10, 10] × [-5, 5]
const Camera kCamera({0, 0}, 10.0, 200, 100);

Style style() {
  Style s;
  s.bodies = {Color::parse("#3b6ea5")};
  return s;
}

// 7 px a character, whatever the text
int sevenEach(const std::string& s) { return static_cast<int>(7 * s.size()); }

}  // namespace

TEST_CASE("a frame's calls in its pixels, y down, with each text's box") {
  DrawList list;
  list.circle({1, 2}, 0.5, {Role::Body, 0, 1.0});
  list.halfPlane({0, -4}, {0, 1}, {Role::StaticBody, -1, 1.0});
  list.text({-10, 5}, "t = 0.500 s", {Role::Caption, -1, 1.0});
  list.text({0, 0}, "ball", {Role::Label, 0, 1.0});
  const PixelDrawList out = render::frame::pixelDrawList(list, style(), kCamera, sevenEach, 20);
  CHECK(out.width == 200);
  CHECK(out.height == 100);
  REQUIRE(out.calls.size() == 4);
  CHECK(out.calls[0].kind == "circle");
  CHECK(out.calls[0].pen == "Body#0");
  CHECK(out.calls[0].color == "#3b6ea5");
  CHECK(out.calls[0].numbers == std::vector<double>{110, 30, 5});
  // the floor's edge point in pixels, its normal up the frame: −y in pixels
  CHECK(out.calls[1].numbers == std::vector<double>{100, 90, 0, -1});
  CHECK(out.calls[1].pen == "StaticBody");
  // a caption's box starts at its point; a label's is centered on it; a line of 20 px text is 24 px
  REQUIRE(out.calls[2].box);
  CHECK(out.calls[2].box->left == 0);
  CHECK(out.calls[2].box->top == 0);
  CHECK(out.calls[2].box->right == 77);
  CHECK(out.calls[2].box->bottom == lineHeightPx(20));
  REQUIRE(out.calls[3].box);
  CHECK(out.calls[3].box->left == 86);
  CHECK(out.calls[3].box->right == 114);
  CHECK(out.calls[3].box->top == std::lround(50 - 0.5 * lineHeightPx(20)));
  CHECK_FALSE(out.calls[0].box);
}

TEST_CASE("a cell's calls moved into a sheet: points and boxes, not radii or normals") {
  DrawList list;
  list.circle({1, 2}, 0.5, {Role::Body, 0, 1.0});
  list.halfPlane({0, -4}, {0, 1}, {Role::StaticBody, -1, 1.0});
  list.text({0, 0}, "ball", {Role::Label, 0, 1.0});
  PixelDrawList sheet{400, 300, {}};
  render::frame::addMoved(sheet, render::frame::pixelDrawList(list, style(), kCamera, sevenEach, 20), 200, 40);
  CHECK(sheet.calls[0].numbers == std::vector<double>{310, 70, 5});
  CHECK(sheet.calls[1].numbers == std::vector<double>{300, 130, 0, -1});
  CHECK(sheet.calls[2].box->left == 286);
  CHECK(sheet.calls[2].numbers == std::vector<double>{300, 90});
  render::frame::addText(sheet, "A: center", {300, 4}, Anchor::TopCenter, 63, 24, Color::parse("#1f1f1f"));
  CHECK(sheet.calls[3].box->left == std::lround(300 - 31.5));
  CHECK(sheet.calls[3].box->top == 4);
}

TEST_CASE("the JSON beside the PNG: width, height and calls, a text's box as four numbers") {
  DrawList list;
  list.text({-10, 5}, "t = 0 s", {Role::Caption, -1, 1.0});
  std::ostringstream json;
  render::frame::writePixelDrawList(json, render::frame::pixelDrawList(list, style(), kCamera, sevenEach, 20));
  CHECK(json.str() ==
        "{\"width\":200,\"height\":100,\"calls\":[\n"
        "{\"kind\":\"text\",\"pen\":\"Caption\",\"color\":\"#1f1f1f\",\"numbers\":[0,0],\"text\":\"t = 0 "
        "s\",\"box\":[0,0,49,24]}]}\n");
  CHECK(render::frame::drawListPathFor("out/a/a-t0.5.png") == "out/a/a-t0.5.json");
}

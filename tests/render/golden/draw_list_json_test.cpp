// A golden frame's draw list: written as JSON and read back equal; compared call by call with the
// numbers within a millionth of the view, and a colour, a text or a call more told apart.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "render/golden/draw_list_json.h"

using namespace render::golden;
using namespace render::draw;

namespace {

DrawnFrame frame(double x, const std::string& bodyColor = "#3b6ea5") {
  DrawList list;
  list.polygon({{x, 0}, {1, 0}, {1, 1}}, {Role::Body, 0, 1.0});
  list.circle({0, 0}, 0.25, {Role::StaticBody, 1, 0.5});
  list.text({0, 1}, "t = 1.000 s \"quoted\"", {Role::Caption, -1, 1.0});
  Style style;
  style.bodies = {Color::parse(bodyColor), Color::parse("#000000")};
  return drawnFrame(list, style, Camera({0, 0}, 2.0, 200, 100));  // a view 4 m wide
}

}  // namespace

TEST_CASE("the JSON reads back as written") {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "draw_list_json_test.json";
  {
    std::ofstream out(path);
    writeDrawnFrame(out, frame(1.0 / 3.0));
  }
  const DrawnFrame back = readDrawnFrame(path.string());
  std::filesystem::remove(path);
  const DrawnFrame written = frame(1.0 / 3.0);
  REQUIRE(back.calls.size() == 3);
  CHECK(back.viewWidth == 4.0);
  CHECK(back.calls[0].numbers == written.calls[0].numbers);  // shortest round-trip numbers
  CHECK(back.calls[0].color == "#3b6ea5");
  CHECK(back.calls[1].pen == "StaticBody#1@0.5");
  CHECK(back.calls[1].numbers.back() == 0.25);
  CHECK(back.calls[2].text == "t = 1.000 s \"quoted\"");
  CHECK(compareDrawnFrames(written, back).empty());
}

TEST_CASE("numbers within 1e-6 of the view's larger side are the same; a colour, a call more are not") {
  CHECK(compareDrawnFrames(frame(0.0), frame(3.9e-6)).empty());
  CHECK(compareDrawnFrames(frame(0.0), frame(4.1e-6)).find("call 1 (polygon Body#0): number 1") == 0);
  CHECK(compareDrawnFrames(frame(0.0), frame(0.0, "#2ca02c")) == "call 1 (polygon Body#0): color #2ca02c, expected #3b6ea5");
  DrawnFrame more = frame(0.0);
  more.calls.push_back(more.calls.front());
  CHECK(compareDrawnFrames(frame(0.0), more) == "4 calls, expected 3");
}

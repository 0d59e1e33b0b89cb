// The label placer (label_place.h) on draw lists: every text of a frame through one placer, so that
// none overlaps another, none covers what another names, labels keep off other bodies, a label
// moved far gets a leader line, and one with no room is dropped and said once.
#include "render/frame/label_place.h"

#include <doctest/doctest.h>

#include "render/draw/draw_list.h"
#include "render/draw/text.h"

using namespace render::draw;
using namespace render::frame;
using sim::core::Vec2;

namespace {

// a 200 × 100 frame of a 2 m × 1 m view centered on the origin: 100 px per meter, text 10 px high,
// 6 px per character
Camera camera() { return Camera(Vec2::Zero(), 1.0, 200, 100); }
LabelPlacer placer(DrawList& list) {
  return LabelPlacer(list, camera(), 10,
                     [](const std::string& s) { return 6 * static_cast<int>(render::draw::decodeUtf8(s).size()); });
}
const Pen kLabel{Role::Label, -1, 1.0};

// the texts the list draws, in pixels, as the placer says they went
bool apart(const std::vector<PlacedText>& placed) {
  for (size_t i = 0; i < placed.size(); ++i)
    for (size_t j = i + 1; j < placed.size(); ++j)
      if (placed[i].box.overlaps(placed[j].box)) return false;
  return true;
}

}  // namespace

TEST_CASE("two labels asking for one spot: the second moves clear, both are drawn") {
  DrawList list;
  LabelPlacer p = placer(list);
  p.label({0, 0}, Vec2::Zero(), "ball", kLabel);
  p.label({0.02, 0}, Vec2::Zero(), "bar", kLabel);
  p.finish();
  REQUIRE(p.placed().size() == 2);
  CHECK(p.dropped().empty());
  CHECK(apart(p.placed()));
  // the first keeps its spot, centered on its anchor (100, 50)
  CHECK(p.placed()[0].box.left == doctest::Approx(88));
  CHECK(p.placed()[0].box.right == doctest::Approx(112));
  // and the second does not cover it
  CHECK_FALSE(p.placed()[1].box.contains(*p.placed()[0].anchor));
  // the canvas gets text, placed, after the shapes
  CHECK(list.lines().size() == 2);
  CHECK(list.lines()[0].starts_with("text Label"));
}

TEST_CASE("a label beyond an arrow's head keeps off another body, and says so with a leader line") {
  DrawList list;
  LabelPlacer p = placer(list);
  // a body right of the arrow's head, where its value would go
  p.polygon({{0.2, -0.2}, {0.9, -0.2}, {0.9, 0.2}, {0.2, 0.2}}, {Role::Body, 1, 1.0});
  p.arrow({-0.5, 0}, {0.1, 0}, {Role::Velocity, 0, 1.0});
  p.label({0.1, 0}, Vec2::UnitX(), "v = 1.00 m/s", {Role::Label, 0, 1.0});
  p.finish();
  REQUIRE(p.placed().size() == 1);
  const PixelBox body{120, 30, 190, 70};
  CHECK_FALSE(p.placed()[0].box.overlaps(body));
  // moved more than a line from beyond the head (110 + 3, 50): a leader line back to the head
  CHECK(p.placed()[0].leader);
  bool leader = false;
  for (const std::string& line : list.lines()) leader = leader || line.starts_with("segment Label#0@0.6");
  CHECK(leader);
}

TEST_CASE("a label may lie on its own body; a body's name stays on it over its own arrows") {
  DrawList list;
  LabelPlacer p = placer(list);
  p.polygon({{-0.5, -0.2}, {0.5, -0.2}, {0.5, 0.2}, {-0.5, 0.2}}, {Role::Body, 0, 1.0});
  p.arrow({0, 0}, {0.4, 0}, {Role::Velocity, 0, 1.0});
  p.label({0, 0}, Vec2::Zero(), "box", {Role::Label, 0, 1.0});
  p.finish();
  REQUIRE(p.placed().size() == 1);
  CHECK(p.placed()[0].box.left == doctest::Approx(91));
  CHECK_FALSE(p.placed()[0].leader);
}

TEST_CASE("text fixed to the frame keeps its place; labels go around it; one over another is dropped") {
  DrawList list;
  LabelPlacer p = placer(list);
  p.text(camera().toWorld({4, 4}), "t = 0.500 s", {Role::Caption, -1, 1.0});
  p.text(camera().toWorld({10, 6}), "slow motion", {Role::Caption, -1, 1.0});
  // a label that would sit on the clock
  p.label(camera().toWorld({30, 10}), Vec2::Zero(), "n̂", kLabel);
  p.finish();
  REQUIRE(p.placed().size() == 2);
  CHECK(p.placed()[0].text == "t = 0.500 s");
  CHECK(p.placed()[0].box.left == 4);
  REQUIRE(p.dropped().size() == 1);
  CHECK(p.dropped()[0].text == "slow motion");
  CHECK(apart(p.placed()));
}

TEST_CASE("a label with no free spot in reach is dropped, never drawn over another, and said once per run") {
  DrawList list;
  LabelPlacer p = placer(list);
  // the frame filled with fixed text, row under row
  for (int row = 0; row < 8; ++row) p.text(camera().toWorld({0, 13.0 * row}), std::string(33, 'x'), {Role::Caption, -1, 1.0});
  p.label({0, 0}, Vec2::Zero(), "E = 2.00 J", kLabel);
  p.finish();
  REQUIRE(p.dropped().size() == 1);
  for (const std::string& line : list.lines()) CHECK(line.find("E = 2.00 J") == std::string::npos);

  std::vector<std::string> said;
  render::frame::DroppedLabels dropped([&](const std::string& m) { said.push_back(m); });
  dropped.report(p.dropped(), 0.5);
  PlacedText later = p.dropped()[0];
  later.text = "E = 1.97 J";
  dropped.report({later}, 0.6);
  REQUIRE(said.size() == 1);
  CHECK(said[0] == "label 'E = 2.00 J' dropped at t = 0.500 s: no free spot for it in the frame");
}

TEST_CASE("a dropped label's warning names its first 60 bytes, cut before a UTF-8 sequence, not a megabyte") {
  std::vector<std::string> said;
  render::frame::DroppedLabels dropped([&](const std::string& m) { said.push_back(m); });
  PlacedText big;
  // 59 bytes, then "é" (2 bytes) across the 60th, then a mebibyte
  big.text = std::string(59, 'a') + "\xc3\xa9" + std::string(1 << 20, 'b');
  dropped.report({big}, 0.5);
  REQUIRE(said.size() == 1);
  CHECK(said[0] ==
        "label '" + std::string(59, 'a') + "… (1048637 bytes)' dropped at t = 0.500 s: no free spot for it in the frame");
}

TEST_CASE("no label covers the anchor of another, even where that would be its nearest spot") {
  DrawList list;
  LabelPlacer p = placer(list);
  // a long value whose preferred box, right of its anchor, covers the point the short label names
  p.label({0.0, 0.0}, Vec2::Zero(), "A", kLabel);
  p.label({-0.3, 0.0}, Vec2::UnitX(), "value = 1.00", kLabel);
  p.finish();
  REQUIRE(p.placed().size() == 2);
  CHECK_FALSE(p.placed()[1].box.grown(1).contains(*p.placed()[0].anchor));
  CHECK(apart(p.placed()));
}

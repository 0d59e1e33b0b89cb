// The poll sheet's grid (panels.cpp): 2 variants side by side, 3-4 as 2 × 2, more in rows of ⌈√n⌉,
// the whole sheet the size asked for, text at least a 40th of its height, and a sheet too small
// for its panels refused with what to do.
#include <doctest/doctest.h>

#include "render/frame/panels.h"
#include "render/jobs/exit_status.h"

using render::frame::panelGrid;

TEST_CASE("the grid: side by side, 2 × 2, then rows; every panel inside the sheet, text a 40th of it") {
  struct Want {
    size_t n;
    int columns, rows;
  };
  for (const Want& w :
       {Want{1, 1, 1}, Want{2, 2, 1}, Want{3, 2, 2}, Want{4, 2, 2}, Want{5, 3, 2}, Want{9, 3, 3}, Want{10, 4, 3}}) {
    INFO(w.n, " panels");
    const render::frame::PanelGrid g = panelGrid(w.n, 1920, 1080, true);
    CHECK(g.columns == w.columns);
    CHECK(g.rows == w.rows);
    CHECK(g.textSize >= 1080 / 40);
    CHECK(g.frameWidth % 2 == 0);
    CHECK(g.frameHeight % 2 == 0);
    for (size_t i = 0; i < w.n; ++i) {
      CHECK(g.frameX(i) >= 0);
      CHECK(g.frameY(i) >= g.titleStrip);
      CHECK(g.frameX(i) + g.frameWidth <= 1920);
      // above the caption's band
      CHECK(g.frameY(i) + g.frameHeight <= 1080 - g.captionBand);
    }
  }
  // two side by side share the width; with no caption the frames take its band
  const render::frame::PanelGrid two = panelGrid(2, 1920, 1080, false);
  CHECK(two.captionBand == 0);
  CHECK(2 * two.frameWidth + two.gap <= 1920);
  CHECK(2 * two.frameWidth + two.gap > 1900);
  CHECK(two.frameY(0) + two.frameHeight > 1070);
}

TEST_CASE("a sheet too small for its panels is refused, saying how to fix it") {
  try {
    (void)panelGrid(400, 320, 180, true);
    FAIL("400 panels fit on 320x180");
  } catch (const render::jobs::UsageError& e) {
    const std::string m = e.what();
    CHECK(m.find("400 panels do not fit on a 320x180 sheet") != std::string::npos);
    CHECK(m.find("give a larger --size") != std::string::npos);
  }
}

TEST_CASE("the caption's band holds the whole caption, in as many lines as it needs, up to four") {
  render::draw::TextRenderer text;
  CHECK(render::frame::sheetCaptionLines("Which block moves fastest?", 1920, 1080, text) == 1);
  const std::string long_ =
      "The intermediate-axis theorem (the tennis racket, the Dzhanibekov effect): a box of 0.1 × 0.4 × 0.8 m and 1 kg spun "
      "at 4 rad/s about one of its principal axes, nudged by 0.1 rad/s about the other two: about the axis of the smallest "
      "moment (A), the middle one (B) and the largest (C).";
  const int lines = render::frame::sheetCaptionLines(long_, 1920, 1080, text);
  CHECK(lines == 3);
  // four variants fill the 2 × 2 grid: the caption has a band under it
  const render::frame::PanelGrid two = panelGrid(4, 1920, 1080, true, 0, 2), three = panelGrid(4, 1920, 1080, true, 0, lines);
  CHECK(three.captionBand > two.captionBand);
  CHECK(three.frameHeight < two.frameHeight);
  // every line of it on the sheet, none cut
  const std::vector<render::frame::SheetText> texts = render::frame::sheetTexts(three, 4, {"A", "B", "C", "D"}, long_, text);
  REQUIRE(texts.size() == 4 + 3);
  for (size_t i = 4; i < texts.size(); ++i) CHECK(texts[i].text.find("…") == std::string::npos);
  CHECK(texts.back().at.y() + text.measure(texts.back().text, three.textSize).ascent <= 1080);
}

TEST_CASE("three variants in 2 × 2: the caption in the empty cell, the frames taking the whole height") {
  render::draw::TextRenderer text;
  const render::frame::PanelGrid g = panelGrid(3, 1920, 1080, true);
  CHECK(g.captionInCell);
  CHECK(g.captionBand == 0);
  CHECK(g.frameY(2) + g.frameHeight > 1070);
  const std::string caption = "Which block moves fastest, and which spins fastest? The ball hits the block's face.";
  const std::vector<render::frame::SheetText> texts = render::frame::sheetTexts(g, 3, {"A", "B", "C"}, caption, text);
  REQUIRE(texts.size() > 3);
  // in the fourth cell, wrapped to its width, whole
  for (size_t i = 3; i < texts.size(); ++i) {
    CHECK(texts[i].at.x() == doctest::Approx(g.frameX(3) + 0.5 * g.frameWidth));
    CHECK(texts[i].at.y() >= g.frameY(3) - g.titleStrip);
    CHECK(text.measure(texts[i].text, g.textSize).width <= g.frameWidth);
    CHECK(texts[i].text.find("…") == std::string::npos);
  }
  // no caption: no cell taken
  CHECK_FALSE(panelGrid(3, 1920, 1080, false).captionInCell);
}

// Text through FreeType: UTF-8 decoding, measuring, and glyphs blended where the anchor says.
#include <doctest/doctest.h>

#include "render/draw/text.h"

using namespace render::draw;

TEST_CASE("UTF-8 decodes to code points; malformed bytes become U+FFFD") {
  CHECK(render::draw::decodeUtf8("aω") == U"aω");
  CHECK(render::draw::decodeUtf8("θ = 1 s") == U"θ = 1 s");
  CHECK(render::draw::decodeUtf8("\xff") == U"\uFFFD");
  CHECK(render::draw::decodeUtf8("\xce") == U"\uFFFD");  // cut short
}

TEST_CASE("longer text is wider; a larger size is taller") {
  render::draw::TextRenderer text;
  const auto a = text.measure("t = 1", 20);
  const auto b = text.measure("t = 1.000 s", 20);
  CHECK(a.width > 0);
  CHECK(b.width > a.width);
  CHECK(text.measure("t = 1", 40).ascent > a.ascent);
  CHECK(text.measure("", 20).width == 0);
}

TEST_CASE("drawn text darkens pixels only around its anchor, over a halo") {
  render::draw::TextRenderer text;
  Image image(200, 100, {1.0, 1.0, 1.0, 1.0});
  const Color black{0.0, 0.0, 0.0, 1.0}, gray{0.5, 0.5, 0.5, 1.0};
  text.draw(image, "Hello", 100, 50, Anchor::Center, 20, black, gray, 2);
  const auto box = text.measure("Hello", 20);
  int dark = 0, halo = 0, outside = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const int v = image.pixel(x, y)[0];
      const bool near = std::abs(x - 100) <= box.width / 2 + 4 && std::abs(y - 50) <= 20;
      if (v < 60) ++dark;
      if (v > 110 && v < 145) ++halo;
      if (v != 255 && !near) ++outside;
    }
  CHECK(dark > 30);
  CHECK(halo > 30);
  CHECK(outside == 0);
}

TEST_CASE("text over the edge is clipped to the image: the part inside is drawn, the rest dropped") {
  render::draw::TextRenderer text;
  const Color black{0.0, 0.0, 0.0, 1.0}, white{1.0, 1.0, 1.0, 1.0};
  // 30 px letters from 5 px above and left of the corner: the first letter's lower right is inside
  Image image(10, 10, white);
  text.draw(image, "clipped text", -5, -5, Anchor::TopLeft, 30, black, white, 3);
  int dark = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) dark += image.pixel(x, y)[0] < 128;
  CHECK(dark > 0);
  CHECK(dark < image.width * image.height);
  // wholly outside: nothing changes (and nothing is written past the buffer; ASan runs this too)
  Image untouched(10, 10, white);
  text.draw(untouched, "far away", 1000, 1000, Anchor::Center, 30, black, white, 3);
  text.draw(untouched, "far away", -1000, -1000, Anchor::Center, 30, black, white, 3);
  CHECK(untouched == Image(10, 10, white));
}

TEST_CASE("a missing font is an error that names it") {
  CHECK_THROWS_WITH_AS(render::draw::TextRenderer("/nonexistent/font.ttf"), doctest::Contains("/nonexistent/font.ttf"),
                       std::runtime_error);
}

TEST_CASE("the line height in pixels without FreeType is the one FreeType measures, at every size") {
  render::draw::TextRenderer text;
  for (int size = 6; size <= 64; ++size) {
    const render::draw::TextBox box = text.measure("Ag", size);
    CAPTURE(size);
    CHECK(render::draw::lineHeightPx(size) == box.ascent + box.descent);
  }
}

// The render: keys of video timing and text (title, title_card, caption, slow_motion): off by
// default, every form read, variants replacing them, bad values at their FILE:LINE:COL.
#include <doctest/doctest.h>

#include <string>

#include "support/drawn_scene.h"
#include "support/render_block.h"

using namespace render_block;

TEST_CASE("timing and text are off by default") {
  const render::scene::RenderDef r = renderOf("");
  CHECK(r.title.empty());
  CHECK(r.titleCard == 0.0);
  CHECK_FALSE(r.captionFromDescription);
  CHECK(r.caption.empty());
  CHECK(r.slowMotion.empty());
}

TEST_CASE("title, title_card, caption and slow_motion are read in each of their forms") {
  const render::scene::RenderDef r =
      renderOf("render: {title: Impulses, title_card: 2.5, caption: true, slow_motion: {factor: 4, window: 0.2}}");
  CHECK(r.title == "Impulses");
  CHECK(r.titleCard == 2.5);
  CHECK(r.captionFromDescription);
  CHECK(r.caption.empty());
  REQUIRE(r.slowMotion.size() == 1);
  CHECK(r.slowMotion[0].factor == 4.0);
  CHECK(r.slowMotion[0].window == 0.2);

  const render::scene::RenderDef s = renderOf(
      "render:\n"
      "  caption: \"The bar turns about its center of mass.\"\n"
      "  slow_motion: [{factor: 2, from: 0.9, to: 1.1}, {factor: 8, window: 0.1}]\n");
  CHECK_FALSE(s.captionFromDescription);
  CHECK(s.caption == "The bar turns about its center of mass.");
  REQUIRE(s.slowMotion.size() == 2);
  CHECK(s.slowMotion[0].factor == 2.0);
  CHECK(s.slowMotion[0].window == 0.0);
  CHECK(s.slowMotion[0].from == 0.9);
  CHECK(s.slowMotion[0].to == 1.1);
  CHECK(s.slowMotion[1].window == 0.1);

  CHECK_FALSE(renderOf("render: {caption: false}").captionFromDescription);
  // "yes" is a caption, not YAML 1.1's true: a caption may well be one word
  CHECK(renderOf("render: {caption: \"yes\"}").caption == "yes");
}

TEST_CASE("a variant replaces the caption and the whole slow_motion list, or turns them off") {
  const std::string text = kBody +
                           "render: {caption: true, slow_motion: [{factor: 4, window: 0.2}, {factor: 2, from: 0, to: 1}]}\n"
                           "variants:\n"
                           "  text: {render: {caption: \"Hello\", slow_motion: {factor: 3, from: 1, to: 2}}}\n"
                           "  off: {render: {caption: false, slow_motion: false}}\n"
                           "  empty: {render: {slow_motion: []}}\n";
  const render::scene::RenderDef t = drawn_scene::load(text, "text").render;
  CHECK_FALSE(t.captionFromDescription);
  CHECK(t.caption == "Hello");
  REQUIRE(t.slowMotion.size() == 1);
  CHECK(t.slowMotion[0].factor == 3.0);
  const render::scene::RenderDef off = drawn_scene::load(text, "off").render;
  CHECK_FALSE(off.captionFromDescription);
  CHECK(off.slowMotion.empty());
  CHECK(drawn_scene::load(text, "empty").render.slowMotion.empty());
}

TEST_CASE("bad timing values name the line and what to write") {
  expectError("render: {title_crad: 2}\n", 3, "did you mean 'title_card'");
  expectError("render:\n  title: [A]\n", 4, "expected text for 'title'");
  expectError("render:\n  title_card: -1\n", 4, "'title_card' must be from 0 to 60, got -1");
  // past a long's range as a frame count: undefined behavior before it was bounded here
  expectError("render:\n  title_card: 1e300\n", 4, "'title_card' must be from 0 to 60, got 1e300");
  expectError("render:\n  caption: {text: A}\n", 4, "true, false or a text");
  expectError("render:\n  slow_motion: true\n", 4, "{factor: f, window: w}");
  expectError("render:\n  slow_motion: 4\n", 4, "or false for 'slow_motion'");
  expectError("render:\n  slow_motion: {window: 0.2}\n", 4, "needs 'factor'");
  expectError("render:\n  slow_motion: {factor: 1, window: 0.2}\n", 4, "above 1 and at most 100");
  expectError("render:\n  slow_motion: {factor: 500, window: 0.2}\n", 4, "above 1 and at most 100");
  expectError("render:\n  slow_motion: {factor: 4}\n", 4, "either 'window' or both 'from' and 'to'");
  expectError("render:\n  slow_motion: {factor: 4, window: 0.2, from: 1, to: 2}\n", 4, "either 'window'");
  expectError("render:\n  slow_motion: {factor: 4, window: 0}\n", 4, "positive");
  expectError("render:\n  slow_motion: {factor: 4, from: 1}\n", 4, "needs 'to'");
  expectError("render:\n  slow_motion: {factor: 4, from: 2, to: 1}\n", 4, "'to' must be later than 'from'");
  expectError("render:\n  slow_motion: {factor: 4, form: 1, to: 2}\n", 4, "did you mean 'from'");
  expectError("render:\n  slow_motion:\n    - {factor: 4, window: 0.1}\n    - [1, 2]\n", 6, "expected {factor");
}

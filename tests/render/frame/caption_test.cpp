// Text laid out to a width: greedy lines, at most so many, "…" where it does not fit (by whole words,
// or code points of a word too long for a line); the caption and the title a scene asks for.
#include <doctest/doctest.h>

#include "render/draw/text.h"
#include "render/frame/caption.h"

using render::frame::wrapLines;
using Lines = std::vector<std::string>;

namespace {

// 10 pixels a code point: widths are easy to count
int tenPerCodePoint(const std::string& s) { return 10 * static_cast<int>(render::draw::decodeUtf8(s).size()); }

}  // namespace

TEST_CASE("words wrap greedily to the width") {
  CHECK(wrapLines("the quick brown fox", 100, 2, tenPerCodePoint) == Lines{"the quick", "brown fox"});
  CHECK(wrapLines("  short \n text ", 100, 2, tenPerCodePoint) == Lines{"short text"});
  CHECK(wrapLines("fits on one", 110, 2, tenPerCodePoint) == Lines{"fits on one"});
  CHECK(wrapLines("", 100, 2, tenPerCodePoint).empty());
}

TEST_CASE("beyond the last line the text ends with an ellipsis") {
  // "brown fox…" is exactly 100 px
  CHECK(wrapLines("the quick brown fox jumps", 100, 2, tenPerCodePoint) == Lines{"the quick", "brown fox…"});
  // no room for "…" after "brown fox": a word goes
  CHECK(wrapLines("the quick brown fox jumps", 95, 2, tenPerCodePoint) == Lines{"the quick", "brown…"});
  CHECK(wrapLines("one two three", 70, 1, tenPerCodePoint) == Lines{"one…"});
}

TEST_CASE("a word wider than a line is cut at a code point, with an ellipsis") {
  CHECK(wrapLines("supercalifragilistic", 100, 2, tenPerCodePoint) == Lines{"supercali…"});
  CHECK(wrapLines("ωωωωωωωωωωωω and", 100, 2, tenPerCodePoint) == Lines{"ωωωωωωωωω…", "and"});
}

TEST_CASE("with the real font every line fits its width") {
  render::draw::TextRenderer text;
  const auto width = [&](const std::string& s) { return text.measure(s, 11).width; };
  const Lines lines = wrapLines(
      "A bar lying at rest is struck at its end by a short horizontal impulse, so that it both translates and spins; "
      "the center of mass moves as if the impulse were applied there.",
      300, 2, width);
  REQUIRE(lines.size() == 2);
  for (const std::string& l : lines) CHECK(width(l) <= 300);
  CHECK(lines[1].substr(lines[1].size() - 3) == "…");
}

TEST_CASE("the first sentence, its white space made single") {
  CHECK(render::frame::firstSentence("A bar is hit at its end.  It spins\nand moves.") == "A bar is hit at its end.");
  CHECK(render::frame::firstSentence("Why? Because.") == "Why?");
  CHECK(render::frame::firstSentence("no stop at all\n here") == "no stop at all here");
  CHECK(render::frame::firstSentence("3.5 m/s. Then") == "3.5 m/s.");
}

TEST_CASE("the caption and the title a scene asks for") {
  render::scene::Scene def;
  def.model.name = "poll_bar_impulse";
  def.model.description = "An impulse at the end. It spins.";
  CHECK(render::frame::captionOf(def).empty());
  def.render.captionFromDescription = true;
  CHECK(render::frame::captionOf(def) == "An impulse at the end.");
  def.render.caption = "Given text";
  CHECK(render::frame::captionOf(def) == "Given text");
  CHECK(render::frame::titleOf(def) == "poll bar impulse");
  def.render.title = "Impulses";
  CHECK(render::frame::titleOf(def) == "Impulses");
}

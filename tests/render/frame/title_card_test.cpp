// The cards of a video (title_card.cpp): the opening card shows the poll's question, never its
// answer; its text is laid out whole (the font shrinks, never a line cut) or refused at its line;
// the closing answer card shows the answer. And what a poll's video and panels draw before the
// answer card: no text of the answer, checked on the draw lists of its frames.
#include <doctest/doctest.h>

#include <sstream>

#include "render/frame/scene_run.h"
#include "render/frame/survey.h"
#include "render/frame/title_card.h"
#include "sim/yaml/scene_error.h"
#include "support/drawn_scene.h"

using render::frame::CardLayout;
using render::frame::layoutCard;

namespace {

const std::string kImpulses = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/lecture/05_impulses.yaml";
const std::string kThree = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/lecture/08_three_collisions_poll.yaml";

// widths without a font: 0.6 em per code point
const render::frame::SizedWidth kEstimate = [](int size) { return render::frame::estimatedWidth(size); };

// the card's lines after the title's, joined by spaces
std::string textOf(const CardLayout& card, size_t titleLines) {
  std::string s;
  for (size_t i = titleLines; i < card.lines.size(); ++i) s += (s.empty() ? "" : " ") + card.lines[i].text;
  return s;
}

std::string words(int n) {
  std::ostringstream s;
  for (int i = 0; i < n; ++i) s << (i ? " " : "") << "word" << i;
  return s.str();
}

}  // namespace

TEST_CASE("a card's text is laid out whole: at its size when it fits, in smaller type when not, else refused") {
  // 1280×720 with 20 px text: the text at 24 px, lines of 960 px (66 code points of 14.4 px)
  const CardLayout small = layoutCard(1280, 720, "Title", words(10), 20, kEstimate);
  REQUIRE(small.fits);
  CHECK(small.lines.front().text == "Title");
  CHECK(small.lines.front().size == 44);
  CHECK(small.lines.at(1).size == 24);
  CHECK(textOf(small, 1) == words(10));
  // a long text: every word still there, in smaller type (down to 15 px), no line ends in "…"
  const CardLayout longer = layoutCard(1280, 720, "Title", words(300), 20, kEstimate);
  REQUIRE(longer.fits);
  CHECK(longer.lines.at(1).size < 24);
  CHECK(longer.lines.at(1).size >= 15);
  CHECK(textOf(longer, 1) == words(300));
  for (const auto& line : longer.lines) CHECK(line.text.find("…") == std::string::npos);
  CHECK(longer.lines.back().y + 1.35 * longer.lines.back().size <= 720);
  // too long even at 15 px: refused, nothing laid out
  const CardLayout tooLong = layoutCard(1280, 720, "Title", words(2000), 20, kEstimate);
  CHECK_FALSE(tooLong.fits);
  CHECK(tooLong.lines.empty());
}

TEST_CASE("a card that cannot fit is refused at the question's FILE:LINE:COL, before anything renders") {
  const render::scene::Scene s =
      drawn_scene::load(drawn_scene::bounce("1", "question: " + words(3000) + "\nrender: {title_card: 2}\n"), "", "long.yaml");
  render::draw::TextRenderer text;
  try {
    render::frame::sceneCard(s.render, s.model.name, s.model.description, false, 1280, 720, text);
    FAIL("the card was laid out");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(std::string(e.what()).starts_with("long.yaml:8:11: the question does not fit on its card at 1280x720"));
  }
}

TEST_CASE("the title card shows the question and never the answer; the answer card shows the answer") {
  for (const std::string& file : {kImpulses, kThree}) {
    const render::scene::Scene s = drawn_scene::loadFile(file, "");
    const auto& poll = s.render.poll;
    REQUIRE_FALSE(poll.question.empty());
    REQUIRE_FALSE(poll.answer.empty());
    render::draw::TextRenderer text;
    const CardLayout card = render::frame::sceneCard(s.render, s.model.name, s.model.description, false, 1280, 720, text);
    // the title, then the question's every word
    std::string shown;
    for (const auto& line : card.lines) shown += line.text + "\n";
    CHECK(shown.find(s.render.title) == 0);
    std::istringstream in(poll.question);
    std::string word;
    while (in >> word) CHECK(shown.find(word) != std::string::npos);
    for (const auto& line : card.lines) CHECK_MESSAGE(poll.answer.find(line.text) == std::string::npos, line.text);
    const CardLayout answer = render::frame::sceneCard(s.render, s.model.name, s.model.description, true, 1280, 720, text);
    CHECK(answer.lines.front().text == "Answer");
    CHECK(poll.answer.find(answer.lines.at(1).text) != std::string::npos);
  }
}

TEST_CASE("a scene with only a description (an answer in it, as before `question:`) still gets its card") {
  const render::scene::Scene s = drawn_scene::load(
      drawn_scene::bounce("1", "description: \"Which way does it go? Answer: back.\"\nrender: {title_card: 2}\n"));
  render::draw::TextRenderer text;
  const CardLayout card = render::frame::sceneCard(s.render, s.model.name, s.model.description, false, 1280, 720, text);
  REQUIRE(card.lines.size() == 2);
  CHECK(card.lines[0].text == "lesson");
  CHECK(card.lines[1].text == "Which way does it go? Answer: back.");
}

TEST_CASE("a poll's frames and its panels' frames draw no text of its answer") {
  for (const std::string& file : {kImpulses, kThree}) {
    const render::scene::Scene base = drawn_scene::loadFile(file, "");
    for (const std::string& variant : base.model.variantNames) {
      const render::scene::Scene s = drawn_scene::loadFile(file, variant);
      const render::frame::RunSurvey survey = render::frame::surveyRun(s);
      render::frame::SceneRun run(s, render::frame::cameraFor(s, survey), survey);
      // the video's frames at 10 fps and the panels' instants, from one run
      std::vector<double> instants = s.render.panels.times;
      for (int k = 0; k <= static_cast<int>(s.model.duration * 10); ++k) instants.push_back(k / 10.0);
      size_t texts = 0;
      run.drawListsAt(instants, 0, [&](size_t, render::draw::DrawList list) {
        for (const auto& call : list.calls()) {
          if (call.text.empty()) continue;
          ++texts;
          // any text of a line's length found in the answer would be the answer shown
          if (call.text.size() >= 8) CHECK_MESSAGE(s.render.poll.answer.find(call.text) == std::string::npos, call.text);
        }
      });
      CHECK(texts > instants.size());  // the clock and labels at least: texts were drawn and looked at
    }
  }
}

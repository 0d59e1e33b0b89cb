// A poll's question apart from its answer (poll_yaml.cpp): `question:` and `answer:` at the top
// level and in a variant, `answer_card` and `reveal` in the render: block, off by default, bad
// values at their FILE:LINE:COL.
#include <doctest/doctest.h>

#include <string>

#include "support/drawn_scene.h"
#include "support/render_block.h"

using namespace render_block;

TEST_CASE("no question, no answer, no answer card, and no panel is ever the answer, by default") {
  const render::scene::PollDef p = renderOf("").poll;
  CHECK(p.question.empty());
  CHECK(p.answer.empty());
  CHECK(p.answerCard == 0.0);
  CHECK_FALSE(p.revealed(0.0));
  CHECK_FALSE(p.revealed(1e9));
}

TEST_CASE("question and answer at the top level, a variant's own, answer_card and reveal") {
  const std::string scene = kBody +
                            "duration: 3\n"
                            "question: Which one?\n"
                            "answer: >\n  This one,\n  surely.\n"
                            "render: {answer_card: 2, reveal: 2.5}\n"
                            "variants:\n  a: {}\n  b: {question: \"Which other?\", answer: \"That one.\"}\n";
  const render::scene::PollDef a = drawn_scene::load(scene, "a").render.poll;
  CHECK(a.question == "Which one?");
  CHECK(a.answer == "This one, surely.\n");
  CHECK(a.line == 4);
  CHECK(a.column == 11);
  CHECK(a.answerCard == 2.0);
  CHECK_FALSE(a.revealed(2.0));
  CHECK(a.revealed(2.5));
  const render::scene::PollDef b = drawn_scene::load(scene, "b").render.poll;
  CHECK(b.question == "Which other?");
  CHECK(b.answer == "That one.");
}

TEST_CASE("in a poll every picture after t = 0 tells the answer, unless reveal makes it a question time") {
  const std::string poll = kBody + "duration: 3\nquestion: Which one?\n";
  const render::scene::PollDef open = drawn_scene::load(poll).render.poll;
  CHECK_FALSE(open.tellsAnswer(0.0));
  CHECK(open.tellsAnswer(0.001));
  CHECK(open.tellsAnswer(3.0));
  // reveal keeps its meaning: the answer from T on, a question before it
  const render::scene::PollDef revealed = drawn_scene::load(poll + "render: {reveal: 2}\n").render.poll;
  CHECK_FALSE(revealed.tellsAnswer(1.5));
  CHECK(revealed.tellsAnswer(2.0));
  // a scene that asks nothing tells no answer but from its reveal time
  const render::scene::PollDef plain = drawn_scene::load(kBody + "duration: 3\n").render.poll;
  CHECK_FALSE(plain.tellsAnswer(2.0));
}

TEST_CASE("a variant's title: its panel's, a key of its own") {
  const std::string scene = kBody + "duration: 1\nvariants:\n  a: {title: \"A: at the center\"}\n  b: {}\n";
  CHECK(drawn_scene::load(scene, "a").render.poll.title == "A: at the center");
  CHECK(drawn_scene::load(scene, "b").render.poll.title.empty());
}

TEST_CASE("bad poll keys are refused at their line") {
  expectError("answer: A.\nrender: {answer_card: -1}\n", 4, "answer_card");
  expectError("render: {answer_card: 2}\n", 3, "give 'answer: TEXT'");
  expectError("duration: 2\nrender: {reveal: 3}\n", 4, "reveal");
  expectError("question: [a, b]\n", 3, "question");
}

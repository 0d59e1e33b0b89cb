// A poll's question apart from its answer: the top-level (or a variant's) `question:` and `answer:`,
// a variant's `title:` (its panel's),
// and the render: block's `answer_card` and `reveal`, read apart from the rest so that each stays small.
#include "render/scene/render_yaml.h"

namespace render::scene {
using sim::yaml::Reader;

void readPoll(const YAML::Node& root, const YAML::Node& block, const Reader& reader, const std::string& file, double duration,
              PollDef& out) {
  reader.optional(root, "question", out.question, &Reader::text);
  reader.optional(root, "answer", out.answer, &Reader::text);
  reader.optional(root, "title", out.title, &Reader::text);
  // the card shows the question, else the description (a scene written before `question:` existed)
  const YAML::Node shown = root["question"] ? root["question"] : root["description"];
  out.file = file;
  if (shown && !shown.Mark().is_null()) out.line = shown.Mark().line + 1, out.column = shown.Mark().column + 1;
  if (const YAML::Node a = root["answer"]; a && !a.Mark().is_null())
    out.answerLine = a.Mark().line + 1, out.answerColumn = a.Mark().column + 1;
  if (!block) return;
  if (const YAML::Node n = block["answer_card"]) {
    out.answerCard = reader.between(n, "answer_card", 0.0, kMaxTitleCard);
    if (out.answerCard > 0.0 && out.answer.empty())
      reader.fail(n, "'answer_card' shows the scene's 'answer:', and it has none; give 'answer: TEXT' at the top level");
  }
  if (const YAML::Node n = block["reveal"]) out.reveal = reader.between(n, "reveal", 0.0, duration);
}

}  // namespace render::scene

// The `render:` keys of video timing and text: title, title_card, caption, slow_motion (section B
// of the lecture pack), read apart from the rest of the block so that each stays small.
#include <cctype>
#include <sstream>

#include "render/scene/render_yaml.h"

namespace render::scene {
using sim::yaml::describe;
using sim::yaml::Reader;

namespace {

// a slow motion this strong already turns a tenth of a second into ten; more is a mistake
constexpr double kMaxSlowFactor = 100.0;

const char* const kSlowForms = "{factor: f, window: w} or {factor: f, from: t0, to: t1}";

std::string lowered(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

SlowMotionDef slowMotion(const YAML::Node& n, const Reader& r) {
  if (!n.IsMap()) r.fail(n, std::string("expected ") + kSlowForms + " for 'slow_motion', got " + describe(n));
  r.checkKeys(n, {"factor", "window", "from", "to"}, "slow_motion");
  SlowMotionDef s;
  const YAML::Node factor = r.required(n, "factor", "slow_motion");
  s.factor = r.positive(factor, "factor");
  if (!(s.factor > 1.0) || s.factor > kMaxSlowFactor) {
    std::ostringstream limit;
    limit << kMaxSlowFactor;
    r.fail(factor,
           "'factor' is how many times slower the video runs: above 1 and at most " + limit.str() + ", got " + factor.Scalar());
  }
  const bool around = static_cast<bool>(n["window"]), explicitly = n["from"] || n["to"];
  if (around == explicitly) r.fail(n, std::string("slow_motion needs either 'window' or both 'from' and 'to': ") + kSlowForms);
  if (around) {
    s.window = r.positive(n["window"], "window");
    return s;
  }
  s.from = r.nonNegative(r.required(n, "from", "slow_motion with 'to'"), "from");
  s.to = r.positive(r.required(n, "to", "slow_motion with 'from'"), "to");
  if (!(s.to > s.from)) r.fail(n["to"], "'to' must be later than 'from'");
  return s;
}

}  // namespace

void readTiming(const YAML::Node& node, const Reader& reader, RenderDef& out) {
  reader.optional(node, "title", out.title, &Reader::text);
  if (node["title_card"]) out.titleCard = reader.between(node["title_card"], "title_card", 0.0, kMaxTitleCard);
  if (const YAML::Node c = node["caption"]) {
    if (!c.IsScalar()) reader.fail(c, "expected true, false or a text for 'caption', got " + describe(c));
    // true or false; any other text (even "yes") is the caption itself
    const std::string lower = lowered(c.Scalar());
    const bool isBoolean = lower == "true" || lower == "false";
    out.captionFromDescription = isBoolean && reader.boolean(c, "caption");
    out.caption = isBoolean ? "" : c.Scalar();
  }
  if (const YAML::Node s = node["slow_motion"]) {
    // a list replaces the base scene's whole (as every list of a variant); false or [] turns it off
    out.slowMotion.clear();
    if (s.IsMap()) {
      out.slowMotion.push_back(slowMotion(s, reader));
    } else if (s.IsSequence()) {
      for (const YAML::Node& one : s) out.slowMotion.push_back(slowMotion(one, reader));
    } else if (!s.IsScalar() || lowered(s.Scalar()) != "false") {
      reader.fail(s, std::string("expected ") + kSlowForms + ", a list of them, or false for 'slow_motion', got " + describe(s));
    }
  }
}

}  // namespace render::scene

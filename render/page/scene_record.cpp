#include "render/page/scene_record.h"

#include <yaml-cpp/yaml.h>

#include <limits>

#include "render/jobs/atomic_file.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/regular_file.h"

namespace render::page {
using namespace render::jobs;

namespace {

void numbers(JsonWriter& j, const std::vector<double>& values) {
  j.beginArray();
  for (double v : values) j.value(v);
  j.endArray();
}

// a bad record: where in it, and what to do (JSON is YAML, so yaml-cpp reads it with its marks)
[[noreturn]] void fail(const std::string& path, const YAML::Mark& mark, const std::string& message) {
  throw UsageError(path + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ": " + message +
                   "; render the scene again to rewrite it");
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  YAML::Node field(const YAML::Node& object, const char* key, YAML::NodeType::value type) const {
    const YAML::Node v = object[key];
    if (!v) fail(path_, object.Mark(), std::string("'") + key + "' is missing");
    if (v.Type() != type) fail(path_, v.Mark(), std::string("'") + key + "' has the wrong type");
    return v;
  }
  std::string text(const YAML::Node& object, const char* key) const {
    return field(object, key, YAML::NodeType::Scalar).Scalar();
  }
  double number(const YAML::Node& object, const char* key) const {
    const YAML::Node v = object[key];
    if (!v) fail(path_, object.Mark(), std::string("'") + key + "' is missing");
    return number(v);
  }
  double number(const YAML::Node& v) const {
    if (v.IsNull()) return std::numeric_limits<double>::quiet_NaN();  // JSON's null for a non-finite value
    if (!v.IsScalar()) fail(path_, v.Mark(), "a number is expected here");
    try {
      return v.as<double>();
    } catch (const YAML::Exception&) {
      fail(path_, v.Mark(), "'" + v.Scalar() + "' is not a number");
    }
  }
  bool flag(const YAML::Node& object, const char* key) const {
    const YAML::Node v = field(object, key, YAML::NodeType::Scalar);
    try {
      return v.as<bool>();
    } catch (const YAML::Exception&) {
      fail(path_, v.Mark(), "'" + v.Scalar() + "' is not true or false");
    }
  }
  std::vector<double> numbers(const YAML::Node& object, const char* key) const {
    std::vector<double> out;
    for (const YAML::Node& v : field(object, key, YAML::NodeType::Sequence)) out.push_back(number(v));
    return out;
  }
  // a file name in the scene's folder: no directories, nothing hidden
  std::string fileName(const YAML::Node& object, const char* key) const {
    const std::string name = text(object, key);
    if (name.empty() || name[0] == '.' || name.find('/') != std::string::npos)
      fail(path_, object[key].Mark(), std::string("'") + key + "' must name a file in the scene's folder");
    return name;
  }

 private:
  std::string path_;
};

}  // namespace

void writeSceneRecord(const SceneRecord& r, const std::string& path) {
  AtomicFile file(path);
  JsonWriter j(file.stream());
  j.beginObject().field("scene", r.scene).field("file", r.file).field("title", r.title).field("description", r.description);
  j.field("question", r.question).field("answer", r.answer);
  j.field("seconds", r.seconds);
  if (r.order > 0) j.field("order", static_cast<double>(r.order));
  j.key("videos").beginArray();
  for (const VideoRecord& v : r.videos)
    j.beginObject().field("variant", v.variant).field("video", v.video).field("poster", v.poster).field("fps", v.fps).endObject();
  j.endArray();
  j.key("panels").beginArray();
  for (const PanelRecord& p : r.panels)
    j.beginObject()
        .field("image", p.image)
        .field("when", p.when)
        .field("question", p.question)
        .field("answer", p.answer)
        .endObject();
  j.endArray();
  j.key("checks").beginArray();
  for (const CheckRecord& c : r.checks) {
    j.beginObject().field("variant", c.variant).field("time", c.time).field("quantity", c.quantity);
    j.key("expected");
    numbers(j, c.expected);
    j.key("actual");
    numbers(j, c.actual);
    j.field("error", c.error).field("tolerance", c.tolerance);
    if (c.earlierRun) j.field("earlier_run", true);
    j.endObject();
  }
  j.endArray();
  j.endObject();
  file.stream() << '\n';
  file.commit();
}

SceneRecord readSceneRecord(const std::string& path) {
  if (const std::string kind = notRegularFile(path); !kind.empty())
    throw UsageError(path + ": " + kind + "; remove it and render the scene again to rewrite it");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw UsageError(path + ": cannot read it; render the scene again to rewrite it");
  } catch (const YAML::Exception& e) {
    fail(path, e.mark, "not a page record (" + e.msg + ")");
  }
  const Reader in(path);
  if (!root.IsMap()) fail(path, root.Mark(), "not a page record (an object with 'scene', 'videos', ...)");
  SceneRecord r;
  r.scene = in.text(root, "scene");
  r.file = in.text(root, "file");
  r.title = in.text(root, "title");
  r.description = in.text(root, "description");
  // a record written before polls had a question and an answer has neither
  r.question = root["question"] ? in.text(root, "question") : "";
  r.answer = root["answer"] ? in.text(root, "answer") : "";
  r.seconds = in.number(root, "seconds");
  // (absent from a record of a scene without order.txt, and from records written before it)
  if (root["order"]) r.order = static_cast<int>(in.number(root, "order"));
  for (const YAML::Node& v : in.field(root, "videos", YAML::NodeType::Sequence))
    r.videos.push_back({in.text(v, "variant"), in.fileName(v, "video"), in.fileName(v, "poster"), in.number(v, "fps")});
  for (const YAML::Node& p : in.field(root, "panels", YAML::NodeType::Sequence))
    r.panels.push_back(
        {in.fileName(p, "image"), in.text(p, "when"), in.flag(p, "question"), p["answer"] && in.flag(p, "answer")});
  for (const YAML::Node& c : in.field(root, "checks", YAML::NodeType::Sequence))
    r.checks.push_back({in.text(c, "variant"), in.number(c, "time"), in.text(c, "quantity"), in.numbers(c, "expected"),
                        in.numbers(c, "actual"), in.number(c, "error"), in.number(c, "tolerance"),
                        c["earlier_run"] && in.flag(c, "earlier_run")});
  return r;
}

}  // namespace render::page

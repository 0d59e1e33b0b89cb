#include "render/golden/record_manifest.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "render/golden/golden_record.h"
#include "render/jobs/json_writer.h"
#include "render/scene/render_def.h"
#include "sim/yaml/scene_error.h"

namespace render::golden {
using render::jobs::formatNumber;
using render::jobs::JsonWriter;

std::string manifestJson(const GoldenRun& run, const RecordInfo& info) {
  std::ostringstream s;
  JsonWriter j(s);
  const GoldenDef& g = info.golden;
  j.beginObject();
  j.field("rigidreel_version", rigidreelVersion()).field("name", run.name);
  j.field("scene_file", info.sceneFile).field("scene_sha256", info.sceneSha256);
  j.field("renderer", run.renderer).field("renderer_version", run.rendererVersion);
  j.key("size").beginArray().value(static_cast<long>(g.width)).value(static_cast<long>(g.height)).endArray();
  j.key("tolerance").beginObject().field("position", g.tolerance.position).field("angle", g.tolerance.angle);
  j.field("velocity", g.tolerance.velocity)
      .field("draw_list", 1e-6)
      .field("pixel_tolerance", static_cast<long>(g.pixelTolerance));
  j.field("pixel_fraction", g.pixelFraction).endObject();
  j.key("checkpoints").beginArray();
  for (const Checkpoint& c : run.checkpoints) j.value(c.t);
  j.endArray();
  j.key("frames").beginArray();
  for (const GoldenFrame& f : run.frames)
    j.beginObject().field("t", f.t).field("png", f.name + ".png").field("draw_list", f.name + ".json").endObject();
  j.endArray().endObject();
  s << '\n';
  return s.str();
}

namespace {

// the manifest's values, each checked at its mark; every fault ends with what to do
class ManifestReader {
 public:
  explicit ManifestReader(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const YAML::Mark& at, const std::string& message) const {
    throw sim::yaml::SceneError(file_, at.line + 1, at.column + 1, message + "; record it again");
  }
  YAML::Node field(const YAML::Node& object, const char* key) const {
    const YAML::Node v = object[key];
    if (!v) fail(object.Mark(), std::string("'") + key + "' is missing");
    return v;
  }
  std::string text(const YAML::Node& object, const char* key) const {
    const YAML::Node v = field(object, key);
    if (!v.IsScalar()) fail(v.Mark(), std::string("'") + key + "' must be a string");
    return v.Scalar();
  }
  double finite(const YAML::Node& v, const std::string& what) const {
    double x = 0.0;
    if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x))
      fail(v.Mark(), "'" + what + "' must be a finite number");
    return x;
  }
  double number(const YAML::Node& v, const std::string& what, double low, double high) const {
    const double x = finite(v, what);
    if (!(x >= low && x <= high))
      fail(v.Mark(), "'" + what + "' is " + formatNumber(x) + ", outside " + formatNumber(low) + " to " + formatNumber(high));
    return x;
  }
  int whole(const YAML::Node& v, const std::string& what, int low, int high) const {
    const double x = finite(v, what);
    if (x != std::floor(x)) fail(v.Mark(), "'" + what + "' must be a whole number, got " + formatNumber(x));
    // (a pixel count as people write it: 100000, not 1e+05)
    if (!(x >= low && x <= high))
      fail(v.Mark(), "'" + what + "' is " + (std::abs(x) < 1e15 ? std::to_string(static_cast<long long>(x)) : formatNumber(x)) +
                         ", outside " + std::to_string(low) + " to " + std::to_string(high));
    return static_cast<int>(x);
  }
  YAML::Node list(const YAML::Node& object, const char* key) const {
    const YAML::Node v = field(object, key);
    if (!v.IsSequence()) fail(v.Mark(), std::string("'") + key + "' must be a list");
    return v;
  }
  // a frame's file: "<name><ending>", the name one of frame-t<T>, nothing outside the record's folder
  std::string frameFile(const YAML::Node& frame, const char* key, const std::string& ending) const {
    const std::string name = text(frame, key);
    if (!name.starts_with("frame-t") || !name.ends_with(ending) || name.find('/') != std::string::npos ||
        name.find('\\') != std::string::npos || name.size() > 200)
      fail(frame[key].Mark(), std::string("'") + key + "' must name a file frame-t<T>" + ending + " in the record's folder");
    return name.substr(0, name.size() - ending.size());
  }

 private:
  const std::string& file_;
};

}  // namespace

RecordManifest manifestText(const std::string& text, const std::string& file, double duration) {
  const ManifestReader r(file);
  YAML::Node m;
  try {
    m = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    r.fail(e.mark, "not a manifest that `rigidreel golden record` wrote (" + e.msg + ")");
  }
  if (!m.IsMap()) r.fail(m.Mark(), "not a manifest that `rigidreel golden record` wrote (an object with 'checkpoints', ...)");
  RecordManifest out;
  out.version = r.text(m, "rigidreel_version");
  out.name = r.text(m, "name");
  out.sceneFile = r.text(m, "scene_file");
  out.sceneSha256 = r.text(m, "scene_sha256");
  out.renderer = r.text(m, "renderer");
  out.rendererVersion = r.text(m, "renderer_version");
  const YAML::Node size = r.list(m, "size");
  if (size.size() != 2) r.fail(size.Mark(), "'size' must be [width, height] in pixels");
  out.golden.width = r.whole(size[0], "size", render::scene::kMinFrameSide, render::scene::kMaxFrameSide);
  out.golden.height = r.whole(size[1], "size", render::scene::kMinFrameSide, render::scene::kMaxFrameSide);
  const YAML::Node t = r.field(m, "tolerance");
  if (!t.IsMap()) r.fail(t.Mark(), "'tolerance' must be an object");
  const double most = 1e300;
  out.golden.tolerance = {r.number(r.field(t, "position"), "position", 0.0, most),
                          r.number(r.field(t, "angle"), "angle", 0.0, most),
                          r.number(r.field(t, "velocity"), "velocity", 0.0, most)};
  out.golden.pixelTolerance = r.whole(r.field(t, "pixel_tolerance"), "pixel_tolerance", 0, 255);
  out.golden.pixelFraction = r.number(r.field(t, "pixel_fraction"), "pixel_fraction", 0.0, 1.0);
  // the checkpoints: within the run, ascending, each once (each is a copy of the run advanced to it)
  for (const YAML::Node& c : r.list(m, "checkpoints")) {
    const double at = r.number(c, "checkpoints", 0.0, duration);
    if (!out.times.checkpoints.empty() && !(at > out.times.checkpoints.back()))
      r.fail(c.Mark(), "the checkpoints must ascend, each given once; t = " + formatNumber(at) +
                           " comes after t = " + formatNumber(out.times.checkpoints.back()));
    out.times.checkpoints.push_back(at);
  }
  if (out.times.checkpoints.empty()) r.fail(m["checkpoints"].Mark(), "'checkpoints' is empty");
  std::set<std::string> names;
  for (const YAML::Node& f : r.list(m, "frames")) {
    if (!f.IsMap()) r.fail(f.Mark(), "a frame must be an object {t, png, draw_list}");
    const double at = r.number(r.field(f, "t"), "t", 0.0, duration);
    if (!std::binary_search(out.times.checkpoints.begin(), out.times.checkpoints.end(), at))
      r.fail(f["t"].Mark(), "the frame at t = " + formatNumber(at) + " is at none of the checkpoints");
    if (!out.times.frames.empty() && !(at > out.times.frames.back()))
      r.fail(f["t"].Mark(), "the frames must ascend, each given once");
    const std::string name = r.frameFile(f, "png", ".png");
    if (r.frameFile(f, "draw_list", ".json") != name)
      r.fail(f["draw_list"].Mark(), "a frame's draw list must be named as its PNG, " + name + ".json");
    if (!names.insert(name).second) r.fail(f["png"].Mark(), "two frames share the file " + name + ".png");
    out.times.frames.push_back(at);
    out.frameNames.push_back(name);
  }
  return out;
}

}  // namespace render::golden

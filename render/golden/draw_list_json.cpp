#include "render/golden/draw_list_json.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/jobs/bounded_read.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/read_limits.h"
#include "sim/yaml/scene_error.h"

namespace render::golden {
using namespace render::draw;
using render::jobs::formatNumber;
using sim::core::Vec2;

DrawnFrame drawnFrame(const DrawList& list, const Style& style, const Camera& camera) {
  DrawnFrame f{camera.worldWidth(), camera.worldHeight(), {}};
  for (const DrawList::Call& c : list.calls()) {
    DrawnCall d{DrawList::kindName(c.kind), penName(c.style), style.penColor(c.style).hex(), c.text, {}};
    for (const Vec2& p : c.points) d.numbers.push_back(p.x()), d.numbers.push_back(p.y());
    if (c.kind == DrawList::Kind::Circle) d.numbers.push_back(c.radius);
    f.calls.push_back(std::move(d));
  }
  return f;
}

void writeDrawnFrame(std::ostream& out, const DrawnFrame& frame) {
  render::jobs::JsonWriter j(out);
  j.beginObject();
  j.key("view").beginObject().field("width", frame.viewWidth).field("height", frame.viewHeight).endObject();
  j.key("calls").beginArray();
  for (const DrawnCall& c : frame.calls) {
    j.beginObject().field("kind", c.kind).field("pen", c.pen).field("color", c.color);
    j.key("numbers").beginArray();
    for (double x : c.numbers) j.value(x);
    j.endArray();
    if (!c.text.empty()) j.field("text", c.text);
    j.endObject();
    out << '\n';
  }
  j.endArray().endObject();
  out << '\n';
}

DrawnFrame readDrawnFrame(const std::string& path) {
  try {
    const YAML::Node root = YAML::Load(render::jobs::readBounded(path, render::jobs::kMaxRecordFileBytes, "golden draw list",
                                                                 "record it again (rigidreel golden record)"));
    DrawnFrame f;
    f.viewWidth = root["view"]["width"].as<double>();
    f.viewHeight = root["view"]["height"].as<double>();
    for (const YAML::Node& c : root["calls"]) {
      DrawnCall d{c["kind"].as<std::string>(),
                  c["pen"].as<std::string>(),
                  c["color"].as<std::string>(),
                  c["text"] ? c["text"].as<std::string>() : "",
                  {}};
      for (const YAML::Node& x : c["numbers"]) d.numbers.push_back(x.as<double>());
      f.calls.push_back(std::move(d));
    }
    return f;
  } catch (const YAML::Exception& e) {
    throw sim::yaml::SceneError(path, e.mark.line + 1, e.mark.column + 1,
                                "not a draw list that `rigidreel golden record` wrote (" + e.msg + "); record it again");
  }
}

std::string compareDrawnFrames(const DrawnFrame& expected, const DrawnFrame& actual, double tolerance) {
  const double allowed = tolerance * std::max(expected.viewWidth, expected.viewHeight);
  const size_t n = std::min(expected.calls.size(), actual.calls.size());
  for (size_t i = 0; i < n; ++i) {
    const DrawnCall& e = expected.calls[i];
    const DrawnCall& a = actual.calls[i];
    const std::string at = "call " + std::to_string(i + 1) + " (" + e.kind + " " + e.pen + ")";
    if (e.kind != a.kind || e.pen != a.pen) return at + " is now " + a.kind + " " + a.pen;
    if (e.color != a.color) return at + ": color " + a.color + ", expected " + e.color;
    if (e.text != a.text) return at + ": text \"" + a.text + "\", expected \"" + e.text + "\"";
    if (e.numbers.size() != a.numbers.size())
      return at + ": " + std::to_string(a.numbers.size()) + " numbers, expected " + std::to_string(e.numbers.size());
    for (size_t k = 0; k < e.numbers.size(); ++k)
      if (!(std::abs(e.numbers[k] - a.numbers[k]) <= allowed))
        return at + ": number " + std::to_string(k + 1) + " is " + formatNumber(a.numbers[k]) + ", expected " +
               formatNumber(e.numbers[k]) + " (off by " + formatNumber(std::abs(e.numbers[k] - a.numbers[k])) + " m, tolerance " +
               formatNumber(allowed) + " m)";
  }
  if (expected.calls.size() != actual.calls.size())
    return std::to_string(actual.calls.size()) + " calls, expected " + std::to_string(expected.calls.size());
  return "";
}

}  // namespace render::golden

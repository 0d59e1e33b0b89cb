#include "render/golden/trace_csv.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "render/jobs/json_writer.h"
#include "sim/yaml/scene_error.h"

namespace render::golden {
using render::jobs::formatNumber;

namespace {

// the columns a trace must have, in the order TraceSample holds them after t and body
const std::array<std::string, 8> kRequired = {"t", "body", "x", "y", "angle", "vx", "vy", "omega"};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(i);
}

}  // namespace

Trace traceText(const std::string& text, const std::string& file, const sim::scene::SceneDef& def) {
  const auto fail = [&](int line, int column, const std::string& message) {
    throw sim::yaml::SceneError(file, line, column, message);
  };
  Trace trace{file, std::vector<std::vector<TraceSample>>(def.bodies.size()), 0};
  std::istringstream in(text);
  std::string line;
  int number = 0;
  std::map<std::string, size_t> column;  // name → field index
  size_t fieldCount = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trimmed(line).empty()) continue;
    const std::vector<std::string> fields = split(line);
    if (column.empty()) {
      for (size_t i = 0; i < fields.size(); ++i) {
        const std::string name = trimmed(fields[i]);
        if (column.count(name)) fail(number, 1, "the column '" + name + "' appears twice in the header");
        column[name] = i;
      }
      for (const std::string& name : kRequired)
        if (!column.count(name))
          fail(number, 1, "the header has no column '" + name + "'; a trace starts with the line " + std::string(kTraceHeader));
      fieldCount = fields.size();
      continue;
    }
    // the column (1-based) where field i starts, for messages
    const auto columnOf = [&](size_t i) {
      size_t at = 1;
      for (size_t k = 0; k < i && k < fields.size(); ++k) at += fields[k].size() + 1;
      return static_cast<int>(at);
    };
    if (fields.size() != fieldCount)
      fail(number, 1,
           "expected " + std::to_string(fieldCount) + " comma-separated values as in the header, got " +
               std::to_string(fields.size()));
    const std::string body = trimmed(fields[column["body"]]);
    const int index = def.bodyIndex(body);
    if (index < 0) {
      std::string known;
      for (const auto& b : def.bodies) known += (known.empty() ? "" : ", ") + b.name;
      fail(number, columnOf(column["body"]), "the scene has no body named '" + body + "' (its bodies: " + known + ")");
    }
    double values[7];
    for (size_t k = 0; k < 7; ++k) {
      const size_t i = column[kRequired[k == 0 ? 0 : k + 1]];
      const std::string field = trimmed(fields[i]);
      size_t used = 0;
      double v = 0.0;
      try {
        v = std::stod(field, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (field.empty() || used != field.size() || !std::isfinite(v))
        fail(number, columnOf(i), "expected a finite number for '" + kRequired[k == 0 ? 0 : k + 1] + "', got '" + field + "'");
      values[k] = v;
    }
    double kinetic = 0.0;
    if (const auto ke = column.find("kinetic_energy"); ke != column.end() && !trimmed(fields[ke->second]).empty()) {
      const std::string field = trimmed(fields[ke->second]);
      size_t used = 0;
      try {
        kinetic = std::stod(field, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != field.size() || !std::isfinite(kinetic))
        fail(number, columnOf(ke->second), "expected a finite number (or nothing) for 'kinetic_energy', got '" + field + "'");
    }
    std::vector<TraceSample>& samples = trace.bodies[index];
    if (!samples.empty() && values[0] < samples.back().t)
      fail(number, columnOf(column["t"]),
           "time goes back for '" + body + "': " + formatNumber(values[0]) + " after " + formatNumber(samples.back().t) +
               " on line " + std::to_string(samples.back().line) + "; list each body's rows in time order");
    samples.push_back({values[0], values[1], values[2], values[3], values[4], values[5], values[6], kinetic, number});
    ++trace.rows;
  }
  if (column.empty()) fail(0, 0, "the trace is empty; it starts with the line " + std::string(kTraceHeader));
  if (trace.rows == 0) fail(number, 1, "the trace has a header but no rows");
  return trace;
}

Trace readTrace(const std::string& path, const sim::scene::SceneDef& def) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sim::yaml::SceneError(path, 0, 0, "cannot read the trace");
  std::ostringstream text;
  text << in.rdbuf();
  return traceText(text.str(), path, def);
}

bool sampleAt(const std::vector<TraceSample>& samples, double t, TraceSample& out, bool before) {
  if (samples.empty() || t < samples.front().t || t > samples.back().t) return false;
  const auto first = std::lower_bound(samples.begin(), samples.end(), t, [](const TraceSample& s, double v) { return s.t < v; });
  if (before && first->t == t) {
    out = *first;
    return true;
  }
  // the first sample later than t, and the last at or before it
  const auto after = std::upper_bound(samples.begin(), samples.end(), t, [](double v, const TraceSample& s) { return v < s.t; });
  const TraceSample& a = *(after - 1);
  if (after == samples.end() || a.t == t) {
    out = a;
    out.t = t;
    return true;
  }
  const TraceSample& b = *after;
  const double f = (t - a.t) / (b.t - a.t);
  const auto mix = [f](double p, double q) { return p + (q - p) * f; };
  out = {t,
         mix(a.x, b.x),
         mix(a.y, b.y),
         mix(a.angle, b.angle),
         mix(a.vx, b.vx),
         mix(a.vy, b.vy),
         mix(a.omega, b.omega),
         mix(a.kineticEnergy, b.kineticEnergy),
         b.line};
  return true;
}

}  // namespace render::golden

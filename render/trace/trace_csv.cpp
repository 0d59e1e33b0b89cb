#include "render/trace/trace_csv.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <map>
#include <optional>
#include <string_view>

#include "render/jobs/bounded_read.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/read_limits.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/scene_error.h"

namespace render::trace {
using render::jobs::formatNumber;

namespace {

// the columns a trace must have: t, body, then the numbers a sample is made of (makeSample's order)
const std::vector<std::string> kRequired = {"t", "body", "x", "y", "angle", "vx", "vy", "omega"};
const std::vector<std::string> kRequired3d = {"t",  "body", "x",  "y",  "z",  "qw", "qx", "qy",
                                              "qz", "vx",   "vy", "vz", "wx", "wy", "wz"};
// rows read between two looks at the interrupt flag
constexpr size_t kRowsPerCheck = 65536;

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  return s;
}

// one field of a row: its text (a quoted field's without its quotes) and the column where it starts
struct Field {
  std::string_view text;
  int column = 1;
};

// The records of a CSV text as RFC 4180 writes them (csv_field.h, python's csv module): a field in
// double quotes may hold commas, line breaks and quotes (doubled); other fields are taken as they
// are, blanks around them trimmed.
class CsvRecords {
 public:
  CsvRecords(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  // the next record's fields, and the line it starts on; false at the end of the text
  bool next(std::vector<Field>& fields, int& line) {
    fields.clear();
    unquoted_.clear();
    if (at_ >= text_.size()) return false;
    line = ++line_;
    lineStart_ = at_;
    for (;;) {
      size_t p = at_;
      while (p < text_.size() && blank(text_[p])) ++p;
      const int column = static_cast<int>(p - lineStart_) + 1;
      if (p < text_.size() && text_[p] == '"') {
        fields.push_back({quoted(p + 1), column});
      } else {
        const size_t end = std::min(text_.find_first_of(",\n", at_), text_.size());
        fields.push_back({trimmed(text_.substr(at_, end - at_)), column});
        at_ = end;
      }
      // at a comma, a line end or the text's end
      if (at_ < text_.size() && text_[at_] == ',') {
        ++at_;
        continue;
      }
      if (at_ < text_.size()) ++at_;  // the '\n'
      // (a "\r\n" line end: the '\r' trimmed with the last field's blanks)
      return true;
    }
  }

 private:
  // the field whose opening quote is before `from`: up to its closing quote, quotes undoubled
  std::string_view quoted(size_t from) {
    const int line = line_;
    const int column = static_cast<int>(from - lineStart_);
    std::string text;
    for (size_t p = from;;) {
      const size_t q = text_.find('"', p);
      if (q == std::string_view::npos)
        throw sim::yaml::SceneError(file_, line, column, "this quoted field has no closing quote (\"); close it");
      // the line breaks inside count as lines of the file
      line_ += static_cast<int>(std::count(text_.begin() + p, text_.begin() + q, '\n'));
      text.append(text_.substr(p, q - p));
      if (q + 1 < text_.size() && text_[q + 1] == '"') {
        text += '"';
        p = q + 2;
        continue;
      }
      p = q + 1;
      while (p < text_.size() && (blank(text_[p]) || text_[p] == '\r')) ++p;
      if (p < text_.size() && text_[p] != ',' && text_[p] != '\n')
        throw sim::yaml::SceneError(file_, line_, static_cast<int>(p - text_.rfind('\n', p)),
                                    "expected a comma after the closing quote of a field; double a quote inside one (\"\")");
      at_ = p;
      break;
    }
    unquoted_.push_back(std::move(text));
    return unquoted_.back();
  }

  std::string_view text_;
  const std::string& file_;
  size_t at_ = 0, lineStart_ = 0;
  int line_ = 0;
  std::deque<std::string> unquoted_;  // this record's quoted fields (a deque: views into them stay valid)
};

// the field as a finite number: what simulate --trace writes (shortest round trip, subnormals too)
// and what other simulators write (a leading '+'); nullopt when it is not one
std::optional<double> finiteNumber(std::string_view s) {
  if (s.starts_with('+')) s.remove_prefix(1);
  if (s.empty() || s.front() == '+' || (s.front() == '-' && s.size() > 1 && s[1] == '+')) return std::nullopt;
  double v = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (end != s.data() + s.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // below the smallest subnormal: strtod rounds to 0; past the largest double: refused
    v = std::strtod(std::string(s).c_str(), nullptr);
  } else if (error != std::errc()) {
    return std::nullopt;
  }
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

// the sample of a row's numbers (t first, then the columns after body in kRequired's order)
TraceSample makeSample(const std::vector<double>& v, double kinetic, int line) {
  return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], kinetic, line};
}
TraceSample makeSample3d(const std::vector<double>& v, double kinetic, int line) {
  TraceSample s{v[0], v[1], v[2], 0.0, v[8], v[9], v[13], kinetic, line};
  s.z = v[3], s.qw = v[4], s.qx = v[5], s.qy = v[6], s.qz = v[7], s.vz = v[10], s.wx = v[11], s.wy = v[12];
  return s;
}

// a 2D or a 3D scene's trace: `required` its columns, `header` the line that has them, `make` a sample of a row
template <class Def>
Trace parseTrace(const std::string& text, const std::string& file, const Def& def, const std::vector<std::string>& required,
                 const std::string& header, TraceSample (*make)(const std::vector<double>&, double, int)) {
  const auto fail = [&](int line, int column, const std::string& message) {
    throw sim::yaml::SceneError(file, line, column, message);
  };
  Trace trace{file, std::vector<std::vector<TraceSample>>(def.bodies.size()), 0};
  CsvRecords records(render::jobs::withoutBom(text), file);
  std::vector<Field> fields;
  int number = 0;
  std::map<std::string, size_t, std::less<>> column;  // name → field index
  size_t fieldCount = 0;
  const size_t count = required.size() - 1;                 // the numbers: every column but body
  std::vector<size_t> indices(count);                       // of t and the numbers after body
  size_t bodyColumn = 0, energyColumn = std::string::npos;  // kinetic_energy's, when there is one
  while (records.next(fields, number)) {
    if (fields.size() == 1 && fields[0].text.empty()) continue;  // a blank line
    if (column.empty()) {
      for (size_t i = 0; i < fields.size(); ++i) {
        const std::string name(fields[i].text);
        if (column.count(name)) fail(number, fields[i].column, "the column '" + name + "' appears twice in the header");
        column[name] = i;
      }
      for (const std::string& name : required)
        if (!column.count(name))
          fail(number, 1, "the header has no column '" + name + "'; a trace starts with the line " + header);
      for (size_t k = 0; k < count; ++k) indices[k] = column[required[k == 0 ? 0 : k + 1]];
      bodyColumn = column["body"];
      if (const auto ke = column.find("kinetic_energy"); ke != column.end()) energyColumn = ke->second;
      fieldCount = fields.size();
      continue;
    }
    if (trace.rows % kRowsPerCheck == 0) render::jobs::checkInterrupted();
    if (fields.size() != fieldCount)
      fail(number, 1,
           "expected " + std::to_string(fieldCount) + " comma-separated values as in the header, got " +
               std::to_string(fields.size()));
    const std::string body(fields[bodyColumn].text);
    const int index = def.bodyIndex(body);
    if (index < 0) {
      std::string known;
      for (const auto& b : def.bodies) known += (known.empty() ? "" : ", ") + sim::yaml::shownName(b.name);
      fail(number, fields[bodyColumn].column,
           "the scene has no body named '" + sim::yaml::shownName(body) + "' (its bodies: " + known + ")");
    }
    std::vector<double> values(count);
    for (size_t k = 0; k < count; ++k) {
      const Field& f = fields[indices[k]];
      const std::optional<double> v = finiteNumber(f.text);
      if (!v)
        fail(number, f.column,
             "expected a finite number for '" + required[k == 0 ? 0 : k + 1] + "', got '" + sim::yaml::shownName(f.text) + "'");
      values[k] = *v;
    }
    double kinetic = 0.0;
    if (energyColumn != std::string::npos && !fields[energyColumn].text.empty()) {
      const Field& f = fields[energyColumn];
      const std::optional<double> v = finiteNumber(f.text);
      if (!v)
        fail(number, f.column,
             "expected a finite number (or nothing) for 'kinetic_energy', got '" + sim::yaml::shownName(f.text) + "'");
      kinetic = *v;
    }
    std::vector<TraceSample>& samples = trace.bodies[index];
    if (!samples.empty() && values[0] < samples.back().t)
      fail(number, fields[indices[0]].column,
           "time goes back for '" + sim::yaml::shownName(body) + "': " + formatNumber(values[0]) + " after " +
               formatNumber(samples.back().t) + " on line " + std::to_string(samples.back().line) +
               "; list each body's rows in time order");
    samples.push_back(make(values, kinetic, number));
    ++trace.rows;
  }
  if (column.empty()) fail(0, 0, "the trace is empty; it starts with the line " + header);
  if (trace.rows == 0) fail(number, 1, "the trace has a header but no rows");
  return trace;
}

std::string traceFile(const std::string& path) {
  return render::jobs::readBounded(path, render::jobs::kMaxTraceBytes, "trace",
                                   "give the trace CSV (`rigidreel simulate --trace` writes one)");
}

}  // namespace

Trace traceText(const std::string& text, const std::string& file, const sim::scene::SceneDef& def) {
  return parseTrace(text, file, def, kRequired, kTraceHeader, makeSample);
}
Trace traceText(const std::string& text, const std::string& file, const sim::scene3d::SceneDef& def) {
  return parseTrace(text, file, def, kRequired3d, kTraceHeader3d, makeSample3d);
}

Trace readTrace(const std::string& path, const sim::scene::SceneDef& def) { return traceText(traceFile(path), path, def); }
Trace readTrace(const std::string& path, const sim::scene3d::SceneDef& def) { return traceText(traceFile(path), path, def); }

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
  out.z = mix(a.z, b.z), out.vz = mix(a.vz, b.vz), out.wx = mix(a.wx, b.wx), out.wy = mix(a.wy, b.wy);
  // q and −q are one rotation: b's taken with the sign nearer a's, the mix normalized
  const double sign = a.qw * b.qw + a.qx * b.qx + a.qy * b.qy + a.qz * b.qz < 0.0 ? -1.0 : 1.0;
  out.qw = mix(a.qw, sign * b.qw), out.qx = mix(a.qx, sign * b.qx), out.qy = mix(a.qy, sign * b.qy);
  out.qz = mix(a.qz, sign * b.qz);
  const double n = std::sqrt(out.qw * out.qw + out.qx * out.qx + out.qy * out.qy + out.qz * out.qz);
  if (n > 0.0) out.qw /= n, out.qx /= n, out.qy /= n, out.qz /= n;
  return true;
}

}  // namespace render::trace

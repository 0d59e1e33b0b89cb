// Reading YAML nodes into typed values, failing with FILE:LINE:COL and a message that says what to
// do. Shared by every layer's reader of a scene file (the model's here, the render: block's and
// stability:'s in the renderer); it includes yaml-cpp, which the simulator never sees.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/core/math.h"
#include "sim/scene/scene_def.h"
#include "sim/yaml/scene_error.h"
#include "sim/yaml/utf8.h"

namespace sim::yaml {

// edit distance with a swap of two neighbours counted as one edit (the optimal string alignment
// form of Damerau's, 1964): the typos a hint should catch are a letter wrong, missing, extra or
// two swapped
inline size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// "; did you mean 'density'?" when one of `valid` is close to `given` (at most a third of its
// letters edited), else "; choose one of: a, b, c": a far guess misleads more than a list
inline std::string nearestOrList(const std::string& given, const std::vector<std::string>& valid) {
  const std::string* nearest = nullptr;
  for (const std::string& k : valid)
    if (!nearest || editDistance(given, k) < editDistance(given, *nearest)) nearest = &k;
  std::string hint;
  if (nearest && 3 * editDistance(given, *nearest) <= given.size()) {
    hint.append("; did you mean '").append(*nearest).append("'?");
    return hint;
  }
  hint.append("; choose one of: ");
  for (size_t i = 0; i < valid.size(); ++i) hint.append(i ? ", " : "").append(valid[i]);
  return hint;
}

inline std::string describe(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "'" + n.Scalar() + "'";
    default: return "nothing";
  }
}

using Keys = std::vector<std::string>;

// a reader's own keys, and those other layers read from the same map (the render: block's, ...)
inline Keys with(Keys own, const Keys& others) {
  own.insert(own.end(), others.begin(), others.end());
  return own;
}

// reads one file's YAML tree into definitions, failing at the first fault with its position
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  // a node without a place in the file (a map a variant's merge made) is reported at `m`: the
  // variant's key
  void placeUnmarked(const YAML::Mark& m) { unmarked_ = m; }

  // where a node is written, for a definition's messages (a merged node: the variant's key)
  sim::core::SourceLoc place(const YAML::Node& at) const {
    const YAML::Mark m = at.Mark().is_null() ? unmarked_ : at.Mark();
    if (m.is_null()) return {1, 1};
    return {m.line + 1, m.column + 1};
  }

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const {
    const YAML::Mark m = at.Mark().is_null() ? unmarked_ : at.Mark();
    if (m.is_null()) throw SceneError(file_, 1, 1, message);
    throw SceneError(file_, m.line + 1, m.column + 1, message);
  }

  // every key of `map` must be one of `allowed`; `what` names the map in messages
  void checkKeys(const YAML::Node& map, const Keys& allowed, const std::string& what) const {
    if (!map.IsMap()) fail(map, "expected a map for " + what + ", got " + describe(map));
    std::vector<std::string> seen;
    for (const auto& kv : map) {
      const std::string key = kv.first.Scalar();
      // yaml-cpp keeps the first of two equal keys silently; say so instead
      if (std::find(seen.begin(), seen.end(), key) != seen.end())
        fail(kv.first, "duplicate key '" + key + "' in " + what + "; give each key once");
      seen.push_back(key);
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      fail(kv.first, "unknown key '" + key + "' in " + what + nearestOrList(key, allowed));
    }
  }

  double number(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, "expected a number for '" + key + "', got " + describe(n));
    try {
      return n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, "expected a number for '" + key + "', got " + describe(n));
    }
  }

  double finite(const YAML::Node& n, const std::string& key) const {
    const double x = number(n, key);
    if (!std::isfinite(x)) fail(n, "'" + key + "' must be a finite number, got " + n.Scalar());
    return x;
  }

  double positive(const YAML::Node& n, const std::string& key) const {
    const double x = number(n, key);
    if (!(x > 0.0) || !std::isfinite(x)) fail(n, "'" + key + "' must be a positive finite number, got " + n.Scalar());
    return x;
  }

  // a number from `least` to `most`: a value that becomes a count must have a bound before it is
  // converted, or a 1e300 is undefined behavior past the integer's range
  double between(const YAML::Node& n, const std::string& key, double least, double most) const {
    const double x = number(n, key);
    if (!(x >= least && x <= most)) {
      std::ostringstream m;
      m << "'" << key << "' must be from " << least << " to " << most << ", got " << n.Scalar();
      fail(n, m.str());
    }
    return x;
  }

  // a whole number from `least` to `most`
  int wholeNumber(const YAML::Node& n, const std::string& key, int least, int most) const {
    const double x = number(n, key);
    if (!(x >= least && x <= most) || x != std::floor(x))
      fail(n, "'" + key + "' must be a whole number from " + std::to_string(least) + " to " + std::to_string(most) + ", got " +
                  n.Scalar());
    return static_cast<int>(x);
  }

  double nonNegative(const YAML::Node& n, const std::string& key) const {
    const double x = number(n, key);
    if (!(x >= 0.0) || !std::isfinite(x)) fail(n, "'" + key + "' must be zero or a positive finite number, got " + n.Scalar());
    return x;
  }

  sim::core::Vec2 vec2(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 2) {
      const std::string got = n.IsSequence() ? "a list of " + std::to_string(n.size()) + " values" : describe(n);
      fail(n, "expected [x, y] for '" + key + "', got " + got);
    }
    return {finite(n[0], key), finite(n[1], key)};
  }
  // the dimension's reader of a vector, for what reads 2D and 3D alike (Reader3d's is vec3)
  static constexpr auto kVector = &Reader::vec2;

  std::string text(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, "expected text for '" + key + "', got " + describe(n));
    if (const size_t at = invalidUtf8At(n.Scalar()); at != std::string::npos)
      fail(n, "'" + key + "' is not UTF-8 text (byte " + std::to_string(at + 1) +
                  " of it): save the file as UTF-8, or write the character as an escape in double quotes (\"\\u00e9\")");
    return n.Scalar();
  }

  bool boolean(const YAML::Node& n, const std::string& key) const {
    if (n.IsScalar()) {
      // the YAML 1.1 spellings, in any case
      std::string s = n.Scalar();
      for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (s == "true" || s == "yes" || s == "on") return true;
      if (s == "false" || s == "no" || s == "off") return false;
    }
    fail(n, "expected true or false for '" + key + "', got " + describe(n));
  }

  // out = read(map[key], key) when the map has `key`: every optional key reads this way, e.g.
  // optional(body, "mass", def.mass, &Reader::positive)
  // (`read` may be a method of a reader derived from this one, such as the 3D reader's vec3)
  template <class T, class Self, class Value>
  void optional(const YAML::Node& map, const std::string& key, T& out,
                Value (Self::*read)(const YAML::Node&, const std::string&) const) const {
    if (const YAML::Node n = map[key]) out = (static_cast<const Self*>(this)->*read)(n, key);
  }

  // the value under `key`, which must be present
  YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& what) const {
    const YAML::Node n = map[key];
    if (!n) fail(map, what + " needs '" + key + "'");
    return n;
  }

  // the name under `key` (required), which must name a body of `scene` (a 2D or a 3D scene's
  // definitions), listing them when it does not
  template <class Scene>
  std::string bodyRef(const YAML::Node& map, const std::string& key, const Scene& scene, const std::string& what) const {
    const YAML::Node n = required(map, key, what);
    const std::string name = text(n, key);
    if (!hasBody(scene.bodies, name)) {
      std::string known;
      for (const auto& b : scene.bodies) known += (known.empty() ? "; the bodies are: " : ", ") + b.name;
      fail(n, "no body named '" + name + "'" + known);
    }
    return name;
  }

  // the coordinate frame a point or a force is written in: "body" or "world"
  std::string coordinateFrame(const YAML::Node& n) const {
    const std::string f = text(n, "frame");  // "body" or "world"
    if (f != "body" && f != "world") fail(n, "frame must be 'body' or 'world', got '" + f + "'");
    return f;
  }

  // an event's or an expect entry's time t, which must lie within [0, duration]
  void checkTime(const YAML::Node& n, double t, double duration, const std::string& what) const {
    if (t < 0.0 || t > duration) {
      std::ostringstream d;
      d << duration;
      fail(n, what + " time " + n.Scalar() + " is outside the scene's duration [0, " + d.str() +
                  "]; move it or lengthen 'duration'");
    }
  }

  // an expect entry's `source`: false for closed_form (the default), true for earlier_run (a value an
  // earlier run gave, kept to catch a change: the page heads it so, not as a closed form)
  bool expectSource(const YAML::Node& entry) const {
    const YAML::Node n = entry["source"];
    if (!n) return false;
    const std::string s = text(n, "source");
    if (s != "closed_form" && s != "earlier_run")
      fail(n, "unknown source '" + s + "'; choose one of: closed_form (the default), earlier_run");
    return s == "earlier_run";
  }

  // one of `names`, listing them when it is not
  template <class Lookup>
  auto named(const YAML::Node& n, const std::string& key, Lookup lookup, const std::string& choices) const {
    const std::string s = text(n, key);
    auto value = lookup(s);
    if (!value) fail(n, "unknown " + key + " '" + s + "'; choose one of: " + choices);
    return *value;
  }

  // whether `bodies` has one named `name`, through one index of the names grown as bodies are
  // read: a scan per force, event and expect entry made loading quadratic (50,000 of each: 96 s).
  // A hit is checked against the list, and a miss looked up again in a new index, so that an index
  // of another list (a reader used twice) is never trusted.
  template <class Bodies>
  bool hasBody(const Bodies& bodies, const std::string& name) const {
    for (int attempt = 0; attempt < 2; ++attempt) {
      if (attempt == 1 || indexedBodies_ != &bodies || indexed_ > bodies.size()) bodyIndex_.clear(), indexed_ = 0;
      indexedBodies_ = &bodies;
      for (; indexed_ < bodies.size(); ++indexed_) bodyIndex_.emplace(bodies[indexed_].name, indexed_);
      const auto it = bodyIndex_.find(name);
      if (it != bodyIndex_.end() && bodies[it->second].name == name) return true;
    }
    return false;
  }

  std::string file_;
  YAML::Mark unmarked_ = YAML::Mark::null_mark();
  // bodyRef's index: the names of `*indexedBodies_`'s first `indexed_` bodies (a copy starts its own)
  mutable std::unordered_map<std::string, size_t> bodyIndex_;
  mutable const void* indexedBodies_ = nullptr;
  mutable size_t indexed_ = 0;
};

// runs `read`, turning a tree shape it did not foresee (yaml-cpp's exceptions) into a SceneError with
// a position: still a message, never a crash
template <class Read>
auto readGuarded(const std::string& file, Read read) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
}

}  // namespace sim::yaml

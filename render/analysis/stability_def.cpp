#include "render/analysis/stability_def.h"

#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "render/analysis/pyramid_rows.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/size_limits.h"
#include "sim/yaml/yaml_reader.h"

namespace render::analysis {

namespace {

// the first dynamic body that a force, spring, drag or event names, and what names it: a search
// that drops or rebuilds the dynamic bodies cannot keep what refers to them
std::optional<std::pair<std::string, std::string>> namedDynamicBody(const sim::scene::SceneDef& model) {
  std::vector<std::pair<std::string, std::string>> named;
  for (const auto& f : model.pointForces) named.emplace_back(f.body, "a force");
  for (const auto& s : model.springs) {
    named.emplace_back(s.body, "a spring");
    if (!s.body2.empty()) named.emplace_back(s.body2, "a spring");
  }
  for (const auto& d : model.drags) named.emplace_back(d.body, "a drag");
  for (const auto& e : model.events) named.emplace_back(e.body, "an event");
  for (const auto& [body, what] : named) {
    const int i = model.bodyIndex(body);
    if (i >= 0 && !model.bodies[i].isStatic) return std::make_pair(body, what);
  }
  return std::nullopt;
}

}  // namespace

StabilityDef readStability(const sim::yaml::SceneSource& source, const sim::scene::SceneDef& model) {
  StabilityDef d;
  const YAML::Node n = source.root[kStabilityKey];
  if (!n) return d;
  return sim::yaml::readGuarded(source.file, [&] {
    const sim::yaml::Reader r(source.file);
    r.checkKeys(n, {"parameter", "body", "from", "to", "stack", "within"}, "stability");
    using Parameter = StabilityDef::Parameter;
    if (const YAML::Node p = n["parameter"]) {
      const std::string name = r.text(p, "parameter");
      const auto parsed = kParameterNames.parse(name);
      if (!parsed) r.fail(p, "unknown stability parameter '" + name + "'; choose one of: " + kParameterNames.list());
      d.parameter = *parsed;
    }
    const bool needsBody = d.parameter == Parameter::Speed || d.parameter == Parameter::MassRatio;
    if (needsBody) d.body = r.bodyRef(n, "body", model, "stability with this parameter");
    else if (n["body"]) r.fail(n["body"], "'body' goes with the parameters speed and mass_ratio");
    // a pyramid's base is grown from the pyramid the scene lists, which must be one
    const PyramidReading pyramid = d.parameter == Parameter::PyramidBase ? readPyramid(model.bodies) : PyramidReading{};
    if (d.parameter == Parameter::PyramidBase) {
      if (!pyramid.rows)
        r.fail(n["parameter"], "pyramid_base grows the pyramid the scene lists, row by row from the bottom: " + pyramid.problem +
                                   "; list the boxes that way, or choose stack_height");
    }
    // a stack height keeps some of the dynamic bodies and a pyramid's base rebuilds them
    if (d.countsBodies()) {
      if (const auto named = namedDynamicBody(model))
        r.fail(n["parameter"], std::string(kParameterNames.name(d.parameter)) + " drops or rebuilds the dynamic bodies, but " +
                                   named->second + " names '" + named->first +
                                   "'; remove it from this scene's study, or choose another parameter");
    }
    // a stack height or a pyramid's base counts bodies: a whole number, within an int before the
    // search converts it; iterations and substeps are whole numbers within what `sim:` takes
    const auto bound = [&](const char* key) -> double {
      if (d.countsBodies()) return r.wholeNumber(n[key], key, 1, std::numeric_limits<int>::max());
      if (d.fewest()) return r.wholeNumber(n[key], key, 1, 1000);
      return r.positive(n[key], key);
    };
    if (n["from"]) d.from = bound("from");
    if (n["to"]) d.to = bound("to");
    if (d.to > 0.0 && d.from > 0.0 && !(d.to > d.from)) r.fail(n["to"], "'to' must be larger than 'from'");
    // a grown pyramid is a scene of its own: it keeps to the scene's bodies limit (a base of 446
    // is 99,681 boxes, under the default 100,000), before any run allocates it
    if (d.parameter == Parameter::PyramidBase) {
      sim::yaml::SizeLimits limits;
      if (source.root["sim"]) sim::yaml::readSizeLimits(r, source.root["sim"], limits);
      const int base = pyramid.rows->base;
      const double statics = static_cast<double>(model.bodies.size()) - base * (base + 1.0) / 2.0;
      double largest = 0.0;
      while ((largest + 1.0) * (largest + 2.0) / 2.0 + statics <= limits.maxBodies) ++largest;
      if (d.to > largest)
        r.fail(n["to"], "a pyramid of base " + std::to_string(static_cast<long>(d.to)) + " has more bodies than the limit of " +
                            std::to_string(limits.maxBodies) +
                            " (the largest base within it: " + std::to_string(static_cast<long>(largest)) +
                            "); lower 'to' or raise the limit with 'sim: {max_bodies: N}'");
      if (d.from > largest)
        r.fail(n["from"],
               "'from' is past the largest base within the bodies limit, " + std::to_string(static_cast<long>(largest)));
      if (d.to == 0.0) d.to = std::min(largest, 1000.0);
      if (d.from > 0.0 && !(d.to > d.from))
        r.fail(n["from"], "'from' must be below 'to', " + std::to_string(static_cast<long>(d.to)));
      // the search starts at the listed base unless told otherwise
      if (d.from == 0.0 && d.to <= base)
        r.fail(n["to"] ? n["to"] : n, "the search starts at the listed pyramid's base, " + std::to_string(base) +
                                          "; give a larger 'to', or a 'from' below it");
    }
    if (n["stack"]) d.stack = r.boolean(n["stack"], "stack");
    if (n["within"]) d.within = r.positive(n["within"], "within");
    if (d.countsBodies() && !n["stack"]) d.stack = true;
    return d;
  });
}

}  // namespace render::analysis

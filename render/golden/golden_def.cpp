#include "render/golden/golden_def.h"

#include "render/scene/render_def.h"
#include "sim/yaml/scene_source.h"
#include "sim/yaml/yaml_reader.h"

namespace render::golden {

GoldenDef readGolden(const sim::yaml::SceneSource& source, double duration) {
  GoldenDef d;
  const YAML::Node n = source.root[kGoldenKey];
  if (!n) return d;
  return sim::yaml::readGuarded(source.file, [&] {
    const sim::yaml::Reader r(source.file);
    r.checkKeys(n, {"at", "impacts", "size", "tolerance", "pixel_tolerance", "pixel_fraction"}, "golden");
    if (const YAML::Node at = n["at"]) {
      if (!at.IsSequence() || at.size() == 0) r.fail(at, "expected a list of times in seconds for 'at', e.g. [0.5, 1]");
      for (const YAML::Node& t : at) {
        const double time = r.finite(t, "at");
        r.checkTime(t, time, duration, "a golden");
        d.at.push_back(time);
      }
    }
    if (n["impacts"]) d.impacts = r.boolean(n["impacts"], "impacts");
    if (const YAML::Node size = n["size"]) {
      if (!size.IsSequence() || size.size() != 2) r.fail(size, "expected [width, height] in pixels for 'size', e.g. [640, 360]");
      d.width = r.wholeNumber(size[0], "size", render::scene::kMinFrameSide, render::scene::kMaxFrameSide);
      d.height = r.wholeNumber(size[1], "size", render::scene::kMinFrameSide, render::scene::kMaxFrameSide);
    }
    if (const YAML::Node t = n["tolerance"]) {
      r.checkKeys(t, {"position", "angle", "velocity"}, "golden tolerance");
      r.optional(t, "position", d.tolerance.position, &sim::yaml::Reader::nonNegative);
      r.optional(t, "angle", d.tolerance.angle, &sim::yaml::Reader::nonNegative);
      r.optional(t, "velocity", d.tolerance.velocity, &sim::yaml::Reader::nonNegative);
    }
    if (n["pixel_tolerance"]) d.pixelTolerance = r.wholeNumber(n["pixel_tolerance"], "pixel_tolerance", 0, 255);
    if (n["pixel_fraction"]) d.pixelFraction = r.between(n["pixel_fraction"], "pixel_fraction", 0.0, 1.0);
    return d;
  });
}

}  // namespace render::golden

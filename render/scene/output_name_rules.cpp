#include "render/scene/output_name_rules.h"

#include <cctype>

namespace render::scene {

namespace {

bool digitAt(const std::string& s, size_t i) { return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); }

}  // namespace

std::string variantNameClash(const std::string& name) {
  // every '-'-separated part: "<scene>-a-t1.png" is variant a's still at t = 1 and variant a-t1's poster
  for (size_t start = 0; start <= name.size();) {
    const size_t end = std::min(name.find('-', start), name.size());
    const std::string part = name.substr(start, end - start);
    if (part.size() > 1 && part[0] == 't' && (digitAt(part, 1) || part[1] == '.')) return "reads as a still's time (-t<seconds>)";
    if (part.starts_with("impact") && digitAt(part, 6)) return "reads as an impact's still (-impact<N>)";
    if (part.starts_with("strobe") && digitAt(part, 6)) return "reads as a strobe still (-strobe<N>)";
    if (part == "panels") return "reads as the poll panels (-panels…)";
    if (part == "frames") return "reads as a video's frames folder (-frames)";
    start = end + 1;
  }
  return "";
}

void checkOutputNames(const sim::yaml::SceneSource& source, const std::string& sceneName, const sim::yaml::Reader& reader) {
  // a lecture pack holds a folder per scene beside its page
  if (sceneName == "index.html") {
    const YAML::Node name = source.root["name"];
    reader.fail(name ? name : source.root,
                "the scene's name 'index.html' is the name of the lecture page beside the scenes' folders; choose another name");
  }
  if (const YAML::Node variants = source.root["variants"]; variants && variants.IsMap())
    for (const auto& kv : variants)
      if (const std::string clash = variantNameClash(kv.first.Scalar()); !clash.empty())
        reader.fail(kv.first, "variant name '" + kv.first.Scalar() + "' " + clash +
                                  ": its files would take another output's name; choose another name");
}

}  // namespace render::scene

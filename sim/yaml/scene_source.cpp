#include "sim/yaml/scene_source.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

namespace {

// base[key] = value, keeping the key's position in the file for messages about a new key
// (looked up through a const node: yaml-cpp's non-const operator[] adds an empty entry)
void setKey(YAML::Node base, const YAML::Node& key, const YAML::Node& value) {
  if (std::as_const(base)[key.Scalar()]) base[key.Scalar()] = value;
  else base.force_insert(key, value);
}

// variants are merged over the scene: maps key by key, the bodies list by name, other values whole
void mergeBodies(YAML::Node base, const YAML::Node& over) {
  for (const YAML::Node& body : over) {
    bool merged = false;
    if (body.IsMap() && body["name"]) {
      for (YAML::Node b : base)
        if (b.IsMap() && std::as_const(b)["name"] && std::as_const(b)["name"].Scalar() == body["name"].Scalar()) {
          for (const auto& kv : body) setKey(b, kv.first, kv.second);
          merged = true;
        }
    }
    if (!merged) base.push_back(body);
  }
}

void mergeMaps(YAML::Node base, const YAML::Node& over) {
  for (const auto& kv : over) {
    const std::string key = kv.first.Scalar();
    const YAML::Node current = std::as_const(base)[key];
    if (current && current.IsMap() && kv.second.IsMap()) {
      mergeMaps(current, kv.second);
    } else if (key == "bodies" && current && current.IsSequence() && kv.second.IsSequence()) {
      mergeBodies(current, kv.second);
    } else {
      setKey(base, kv.first, kv.second);
    }
  }
}

// the variants' names, and the chosen one merged over the base scene
void mergeVariant(const Reader& r, SceneSource& s) {
  const YAML::Node variants = s.root["variants"];
  if (variants) {
    if (!variants.IsMap()) r.fail(variants, "'variants' must be a map from names to changes, got " + describe(variants));
    for (const auto& kv : variants) {
      if (!kv.second.IsMap() && !kv.second.IsNull())
        r.fail(kv.second, "variant '" + kv.first.Scalar() + "' must be a map of changes, got " + describe(kv.second));
      s.variantNames.push_back(kv.first.Scalar());
      if (kv.second.IsMap() && kv.second["dimensions"])
        r.fail(kv.second["dimensions"], "a variant cannot change 'dimensions': a scene is 2D or 3D throughout");
    }
  }
  if (s.variant.empty()) return;
  if (std::find(s.variantNames.begin(), s.variantNames.end(), s.variant) == s.variantNames.end()) {
    std::string known;
    for (const auto& n : s.variantNames) known += (known.empty() ? "" : ", ") + n;
    r.fail(variants ? variants : s.root, "unknown variant '" + s.variant + "'; " +
                                             (known.empty() ? "this scene has no variants" : "this scene has: " + known));
  }
  const YAML::Node changes = variants[s.variant];
  if (changes.IsMap()) {
    if (changes["variants"]) r.fail(changes["variants"], "a variant cannot define variants");
    mergeMaps(s.root, changes);
  }
}

std::string stem(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  if (base.size() > 5 && base.ends_with(".yaml")) base.resize(base.size() - 5);
  else if (base.size() > 4 && base.ends_with(".yml")) base.resize(base.size() - 4);
  return base;
}

}  // namespace

SceneSource sceneSourceText(const std::string& text, const std::string& file, const std::string& variant) {
  SceneSource s{file, stem(file), variant, {}, {}, 2};
  try {
    s.root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, "invalid YAML: " + e.msg);
  }
  if (!s.root || s.root.IsNull()) throw SceneError(file, 1, 1, "the scene is empty; it needs at least 'bodies:'");
  readGuarded(file, [&] {
    const Reader r(file);
    if (!s.root.IsMap()) r.fail(s.root, "a scene is a map with at least 'bodies:'; got " + describe(s.root));
    mergeVariant(r, s);
    if (const YAML::Node d = std::as_const(s.root)["dimensions"]) {
      const double n = r.number(d, "dimensions");
      if (n != 2.0 && n != 3.0) r.fail(d, "'dimensions' is 2 (the default: a plane) or 3 (space), got " + d.Scalar());
      s.dimensions = static_cast<int>(n);
    }
  });
  return s;
}

SceneSource readSceneSource(const std::string& path, const std::string& variant) {
  if (std::filesystem::is_directory(path))
    throw SceneError(path, 0, 0, "is a directory, not a scene file; give the path of a .yaml file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, 0, 0, "cannot open the scene file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  return sceneSourceText(text.str(), path, variant);
}

}  // namespace sim::yaml

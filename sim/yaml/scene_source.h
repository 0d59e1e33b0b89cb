// One scene file as a YAML tree with the chosen variant merged in: what every layer's reader reads
// its own keys from (the model here in sim/yaml, the render: block in the renderer, stability: in
// the analysis), so that the file is parsed and merged once.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "sim/yaml/scene_error.h"

namespace sim::yaml {

// the largest scene file read, bytes: yaml-cpp holds about 100 bytes of memory per byte of a file
// (`check` of 250,000 bodies in 16 MB: 16 s, 1.5 GB at its peak; 63 MB of bodies reached 3.6 GB
// and grew), so this keeps a load under 2 GB
inline constexpr size_t kMaxSceneBytes = size_t{16} << 20;

struct SceneSource {
  std::string file;                       // as given: it names the file in messages
  std::string stem;                       // the file name without .yaml: the default scene name
  std::string variant;                    // the variant merged in, empty for the base scene
  std::vector<std::string> variantNames;  // every variant the file defines, in order
  YAML::Node root;                        // a map; variants deep-merged over the base scene
  int dimensions = 2;                     // `dimensions:`, 2 (the default) or 3; no variant changes it
  // the merged variant's key: where a fault in a map the merge made (which has no place in the file) is
  // reported; null for the base scene
  YAML::Mark variantMark = YAML::Mark::null_mark();
};

// A scene file read and parsed once: the base scene before any variant, checked to be a map whose
// variants are well named and whose `dimensions` is 2 or 3. Every variant is merged from it
// (sceneSource), so that a command reads a file's dimension and all its variants from one parse.
struct SceneDocument {
  std::string file;                       // as given: it names the file in messages
  std::string stem;                       // the file name without .yaml: the default scene name
  YAML::Node root;                        // the base scene, as the file has it; never changed
  std::vector<std::string> variantNames;  // every variant the file defines, in order
  int dimensions = 2;                     // `dimensions:`, 2 (the default) or 3
  size_t bytes = 0;                       // the file's size: the bound of a variant's merge
};

// the file at `path`, which must be a regular file of at most kMaxSceneBytes; throws SceneError
SceneDocument readSceneDocument(const std::string& path);
// the same from text; `file` names it in messages
SceneDocument sceneDocumentText(const std::string& text, const std::string& file);
// the document with the named variant merged over it ("" for the base scene): maps key by key, the
// bodies list by name, other values whole. Throws SceneError for an unknown variant or a fault in
// its changes.
SceneSource sceneSource(const SceneDocument& document, const std::string& variant = "");

// the scene in `path`, with the named variant deep-merged over it ("" for the base scene): maps key
// by key, the bodies list by name, other values whole. The merge builds new maps and never changes
// a node of the file, so that aliases (&a, *a) stay what they were written as. Throws
// SceneError.
SceneSource readSceneSource(const std::string& path, const std::string& variant = "");
// the same from text; `file` names it in messages
SceneSource sceneSourceText(const std::string& text, const std::string& file, const std::string& variant = "");

}  // namespace sim::yaml

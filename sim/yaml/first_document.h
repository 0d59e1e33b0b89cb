// A YAML text's first document as yaml-cpp's nodes, and where a second one starts: one parse.
// YAML::Load ignores every document after the first, and yaml-cpp's own builder (NodeBuilder) is
// not installed, so this builds the nodes from the parser's events as that builder does.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

namespace sim::yaml {

struct FirstDocument {
  YAML::Node root;                   // null for a text with no document
  std::optional<YAML::Mark> second;  // where a second document starts; its contents are not read
};

// throws YAML::ParserException (YAML::DeepRecursion for nesting past the parser's limit)
FirstDocument loadFirstDocument(const std::string& text);

}  // namespace sim::yaml

#include "render_yaml.h"

namespace sim::yaml {

void readRender(const YAML::Node& node, const Reader& reader, RenderDef&) {
  reader.checkKeys(node, {"size"}, "render");
}

}  // namespace sim::yaml

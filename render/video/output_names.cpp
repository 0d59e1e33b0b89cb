#include "render/video/output_names.h"

#include <cstdio>

namespace render::video {

std::string outputBase(const sim::scene::SceneDef& def) { return def.variant.empty() ? def.name : def.name + "-" + def.variant; }

std::string timeForName(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", t);
  return buf;
}

std::string strobeSuffix(int strobe) { return strobe > 0 ? "-strobe" + std::to_string(strobe) : ""; }

std::string panelsFileName(const std::string& scene, const std::string& when, int strobe) {
  return scene + "-panels" + when + strobeSuffix(strobe) + ".png";
}

}  // namespace render::video

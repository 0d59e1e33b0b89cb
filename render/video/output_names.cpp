#include "render/video/output_names.h"

#include <cstdio>
#include <map>

namespace render::video {

std::string outputBase(const sim::scene::SceneDef& def) { return outputBase(def.name, def.variant); }

std::string outputBase(const std::string& scene, const std::string& variant) {
  return variant.empty() ? scene : scene + "-" + variant;
}

namespace {

std::string timeWithDigits(double t, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, t == 0.0 ? 0.0 : t);
  return buf;
}

}  // namespace

std::string timeForName(double t) { return timeWithDigits(t, 6); }

std::vector<std::string> timesForNames(const std::vector<double>& times) {
  // 17 significant digits tell any two doubles apart
  for (int digits = 6;; ++digits) {
    std::map<std::string, double> seen;
    bool distinct = true;
    std::vector<std::string> names;
    for (double t : times) {
      names.push_back(timeWithDigits(t, digits));
      const auto [it, added] = seen.emplace(names.back(), t);
      distinct = distinct && (added || it->second == t || (it->second == 0.0 && t == 0.0));
    }
    if (distinct || digits >= 17) return names;
  }
}

std::string strobeSuffix(int strobe) { return strobe > 0 ? "-strobe" + std::to_string(strobe) : ""; }

std::string panelsFileName(const std::string& scene, const std::string& when, int strobe) {
  return scene + "-panels" + when + strobeSuffix(strobe) + ".png";
}

}  // namespace render::video

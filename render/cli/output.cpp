#include "render/cli/output.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "render/cli/commands.h"
#include "render/scene/render_def.h"

namespace render::cli {

FrameSize parseSize(const std::string& text, const std::string& option) {
  static const std::regex form(R"((\d{1,6})[xX](\d{1,6}))");
  std::smatch m;
  if (!std::regex_match(text, m, form))
    throw UsageError(option + ": expected WIDTHxHEIGHT in pixels, e.g. 1280x720, got '" + text + "'");
  const FrameSize s{std::stoi(m[1]), std::stoi(m[2])};
  const auto inRange = [](int v) { return v >= render::scene::kMinFrameSide && v <= render::scene::kMaxFrameSide; };
  if (!inRange(s.width) || !inRange(s.height))
    throw UsageError(option + ": each side must be from " + std::to_string(render::scene::kMinFrameSide) + " to " +
                     std::to_string(render::scene::kMaxFrameSide) + " pixels, got " + text);
  if (s.width % 2 || s.height % 2)
    throw UsageError(option + ": sides must be even (H.264 video halves the color planes); try " +
                     std::to_string(s.width + s.width % 2) + "x" + std::to_string(s.height + s.height % 2));
  return s;
}

void checkFps(double fps, const std::string& option) {
  if (!(fps > 0.0) || !(fps <= render::scene::kMaxFps))
    throw UsageError(option + ": frames per second must be above 0 and at most 1000, got " + timeForName(fps));
}

std::string outputDirectory(const std::string& root, const std::string& scene) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(root) / scene;
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir))
    throw UsageError("-o: cannot create the output directory " + dir.string() + " (" +
                     (error ? error.message() : "a file is in the way") + "); choose another with -o DIR");
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError("-o: cannot write in " + dir.string() + "; choose another directory with -o DIR");
  return dir.string();
}

std::string outputBase(const sim::scene::SceneDef& def) { return outputBase(def.name, def.variant); }

std::string outputBase(const std::string& scene, const std::string& variant) {
  return variant.empty() ? scene : scene + "-" + variant;
}

std::string timeForName(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", t);
  return buf;
}

}  // namespace render::cli

namespace render::cli {

std::string strobeSuffix(int strobe) { return strobe > 0 ? "-strobe" + std::to_string(strobe) : ""; }

std::string panelsFileName(const std::string& scene, const std::string& when, int strobe) {
  return scene + "-panels" + when + strobeSuffix(strobe) + ".png";
}

}  // namespace render::cli

#include "render/cli/lecture_files.h"

#include <algorithm>
#include <filesystem>

#include "render/cli/commands.h"
#include "render/cli/scene_options.h"
#include "render/cli/scene_order.h"
#include "render/jobs/regular_file.h"
#include "sim/scene3d/scene_build.h"

namespace render::cli {
using namespace render::jobs;
namespace fs = std::filesystem;

std::vector<std::string> lectureSceneFiles(const std::vector<std::string>& arguments) {
  std::vector<std::string> files;
  for (const std::string& a : arguments) {
    std::error_code error;
    if (fs::is_directory(a, error)) {
      std::vector<std::string> found;
      for (const fs::directory_entry& e : fs::directory_iterator(a, error))
        if (e.path().extension() == ".yaml" && !e.is_directory()) found.push_back(e.path().string());
      // a stray FIFO named *.yaml would block the pack in open() before anything renders
      for (const std::string& f : found)
        if (const std::string kind = notRegularFile(f); !kind.empty())
          throw UsageError(f + ": " + kind + "; remove it from the folder or give the scene files one by one");
      if (found.empty()) throw UsageError(a + ": no scene files (*.yaml) in this directory; give a directory of scenes");
      for (const std::string& f : orderedSceneFiles(a, found)) files.push_back(f);
    } else if (fs::exists(a, error)) {
      if (const std::string kind = notRegularFile(a); !kind.empty())
        throw UsageError(a + ": " + kind + "; give scene files (*.yaml) or directories of them");
      files.push_back(a);
    } else {
      throw UsageError(a + ": no such file or directory; give scene files (*.yaml) or directories of them");
    }
  }
  return files;
}

render::video::LoadVariant lectureLoader(const OpenScene& file) {
  return [file](const std::string& variant) {
    render::scene::Scene scene = file.read(variant).scene;
    if (!variant.empty() || scene.model.variantNames.empty()) {
      warnOfModel(scene.model, file.path());
      (void)startWorld(scene.model, file.path());
    }
    return scene;
  };
}

render::video::LoadVariant3d lectureLoader3d(const OpenScene& file) {
  return [file](const std::string& variant) {
    render::scene3d::Scene scene = file.read3d(variant).scene;
    try {
      (void)sim::scene3d::buildWorld(scene.model);
    } catch (const std::invalid_argument& e) {
      throw sim::yaml::SceneError(file.path(), 0, 0, (variant.empty() ? "" : "variant '" + variant + "': ") + e.what());
    }
    return scene;
  };
}

}  // namespace render::cli

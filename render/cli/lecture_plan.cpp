#include "render/cli/lecture_plan.h"

#include <algorithm>
#include <filesystem>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/frame/survey.h"
#include "sim/yaml/scene_yaml.h"

namespace render::cli {
using namespace render::draw;
using namespace render::frame;
using namespace render::scene;

namespace fs = std::filesystem;

std::vector<std::string> lectureSceneFiles(const std::vector<std::string>& arguments) {
  std::vector<std::string> files;
  for (const std::string& a : arguments) {
    std::error_code error;
    if (fs::is_directory(a, error)) {
      std::vector<std::string> found;
      for (const fs::directory_entry& e : fs::directory_iterator(a, error))
        if (e.path().extension() == ".yaml" && !e.is_directory()) found.push_back(e.path().string());
      if (found.empty()) throw UsageError(a + ": no scene files (*.yaml) in this directory; give a directory of scenes");
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(a, error)) {
      files.push_back(a);
    } else {
      throw UsageError(a + ": no such file or directory; give scene files (*.yaml) or directories of them");
    }
  }
  return files;
}

namespace {

// the poll panels must exist for every variant, or the pack would fail after its videos: the default
// time is the shortest variant's duration; with `impacts`, every variant must have one (times asked
// for are checked against each variant's duration when the variant is read)
void checkPanels(LecturePlan& plan) {
  render::scene::PanelsDef& panels = plan.base.render.panels;
  const bool defaulted = panels.line == 0;
  auto fail = [&](const std::string& message) {
    throw sim::yaml::SceneError(plan.file, panels.line, panels.column, message);
  };
  double shortest = plan.base.model.duration;
  for (const render::scene::Scene& def : plan.videos) shortest = std::min(shortest, def.model.duration);
  if (defaulted && !panels.times.empty()) panels.times = {shortest};
  if (panels.impacts)
    for (const render::scene::Scene& def : plan.videos) {
      const size_t impacts = surveyRun(def).impactTimes.size();
      plan.mostImpacts = std::max(plan.mostImpacts, impacts);
      if (impacts == 0)
        fail("'panels: impacts' needs an impact in every variant, and variant '" + def.model.variant +
             "' has none; give panel times instead, e.g. [0, " + timeForName(def.model.duration) + "]");
    }
}

}  // namespace

LecturePlan planLecture(const std::string& file) {
  if (isSceneFile3d(file)) {
    LecturePlan plan = planLecture3d(file);
    checkPanels(plan);
    return plan;
  }
  LecturePlan plan{file, readSceneFile(file).scene, {}};
  if (plan.base.model.variantNames.empty()) plan.videos.push_back(plan.base);
  for (const std::string& v : plan.base.model.variantNames) plan.videos.push_back(readSceneFile(file, v).scene);
  for (const render::scene::Scene& def : plan.videos) (void)startWorld(def.model, file);
  checkPanels(plan);
  return plan;
}

std::vector<std::string> lectureOutputs(const LecturePlan& plan, const std::string& root) {
  const std::string dir = (fs::path(root) / plan.base.model.name).string() + "/";
  std::vector<std::string> paths;
  for (const render::scene::Scene& def : plan.videos) {
    paths.push_back(dir + outputBase(def.model) + ".mp4");
    paths.push_back(dir + outputBase(def.model) + ".png");
  }
  // as `snapshot --panels` names them: the first variant's strobe, one image per time or impact
  const render::scene::PanelsDef& panels = plan.base.render.panels;
  const int strobe = plan.videos.front().render.strobe;
  for (double t : panels.times) paths.push_back(dir + panelsFileName(plan.base.model.name, "-t" + timeForName(t), strobe));
  if (panels.impacts)
    for (size_t i = 1; i <= plan.mostImpacts; ++i)
      paths.push_back(dir + panelsFileName(plan.base.model.name, "-impact" + std::to_string(i), strobe));
  return paths;
}

}  // namespace render::cli
